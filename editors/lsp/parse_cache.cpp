#include "editors/lsp/parse_cache.h"

#include "interpreter/ast/parse.h"

namespace strun::editors::lsp {

namespace {

void replay(const std::vector<Diagnostic>& diagnostics, CompileLog& log) {
    for (const Diagnostic& d : diagnostics) log.repeat(d);
}

}  // namespace

std::map<int, std::shared_ptr<ast::CompilationUnit>> ParseCache::units(const SourceSet& sources, const std::vector<int>& files,
                                                                       CompileLog& log) {
    std::vector<int> missing;
    std::set<std::string> used;
    for (int f : files) {
        const SourceFile& file = sources.file(f);
        used.insert(file.path);
        auto it = entries_.find(file.path);
        if (it == entries_.end() || it->second.index != f || it->second.text != file.text) missing.push_back(f);
    }
    // Parsed together (two at a time, on large stacks, as compileProject parses).
    CompileLog fresh;
    std::vector<ast::CompilationUnit> parsedUnits = ast::parseFiles(sources, missing, fresh);
    for (size_t k = 0; k < missing.size() && k < parsedUnits.size(); ++k) {
        const SourceFile& file = sources.file(missing[k]);
        Entry& e = entries_[file.path];
        e.text = file.text;
        e.index = missing[k];
        e.unit = std::make_shared<ast::CompilationUnit>(std::move(parsedUnits[k]));
        e.diagnostics.clear();
        for (const Diagnostic& d : fresh.messages())
            if (d.loc.file == missing[k]) e.diagnostics.push_back(d);
    }
    // Files no longer in the project are forgotten.
    for (auto it = entries_.begin(); it != entries_.end();) it = used.count(it->first) ? std::next(it) : entries_.erase(it);
    std::map<int, std::shared_ptr<ast::CompilationUnit>> out;
    for (int f : files) {
        const Entry& e = entries_.at(sources.file(f).path);
        replay(e.diagnostics, log);
        out.emplace(f, e.unit);
    }
    parsed_ = missing.size();
    reused_ = files.size() - missing.size();
    return out;
}

}  // namespace strun::editors::lsp
