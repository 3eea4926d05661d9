// The user's files as parsed the last time, for strun lsp: after an edit
// only the changed file is parsed again; every other file's AST (and its
// syntax diagnostics) is lent to the next compile unchanged (decision 0270).
// A file is parsed again when its text or its index in the compile's
// SourceSet changed (positions carry the index).
#pragma once

#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "interpreter/ast/ast.h"
#include "interpreter/source/source_set.h"

namespace strun::editors::lsp {

class ParseCache {
public:
    // The units of `files` (indices of `sources`), parsing those not cached;
    // their syntax diagnostics are added to `log` in the order of `files`.
    // Units are shared: a compile's model points into them, and an older
    // compile may still be answering requests.
    std::map<int, std::shared_ptr<ast::CompilationUnit>> units(const SourceSet& sources, const std::vector<int>& files, CompileLog& log);
    size_t reused() const { return reused_; }  // by the last call
    size_t parsed() const { return parsed_; }

private:
    struct Entry {
        std::string text;
        int index = -1;
        std::shared_ptr<ast::CompilationUnit> unit;
        std::vector<Diagnostic> diagnostics;
    };
    std::map<std::string, Entry> entries_;  // by path
    size_t reused_ = 0, parsed_ = 0;
};

}  // namespace strun::editors::lsp
