// The source files of one project and the compile diagnostics reported on them.
// Every stage reports errors here, with a location; the CLI prints them
// compiler style: FILE:LINE:COL: error: MESSAGE.
#pragma once

#include <algorithm>
#include <ostream>
#include <string>
#include <vector>

#include "interpreter/ast/ast.h"
#include "interpreter/source/diagnostic.h"
#include "interpreter/source/diagnostic_code.h"

namespace strun {

// Where one line of a converted source (ST assembled from an XML file) comes
// from: line `line` of the original file, columns shifted by `colShift`; a
// line strun wrote itself (END_FUNCTION_BLOCK, a declaration built from XML
// elements) points at `fixedCol` of the element it was made from. ST made
// from a graphical element (LD, FBD, SFC) names it in `element` (`rung 3,
// contact 'bStart'`), which diagnostics on the line add as a note.
struct LineOrigin {
    int line = 1;
    int colShift = 0;
    int fixedCol = -1;
    std::string element;
};

struct SourceFile {
    std::string path;  // as given on the command line
    std::string text;  // ST text (for XML inputs: the ST assembled from them)
    std::vector<LineOrigin> origins;  // empty for ST files; else one per line of `text`
    std::string userText;  // for XML inputs: the XML itself, which diagnostics quote

    // The text the user has, which diagnostics quote: the XML for converted sources.
    const std::string& shownText() const { return userText.empty() ? text : userText; }

    // The position in the file the user has (the XML line and column) of a position in `text`.
    std::pair<int, int> original(int line, int col) const {
        if (origins.empty() || line < 1) return {line, col};
        const LineOrigin& o = origins[std::min<size_t>(static_cast<size_t>(line), origins.size()) - 1];
        return {o.line, o.fixedCol >= 0 ? o.fixedCol : col + o.colShift};
    }
    // The graphical element a line of `text` was made from, or "".
    const std::string& element(int line) const {
        static const std::string none;
        if (origins.empty() || line < 1) return none;
        return origins[std::min<size_t>(static_cast<size_t>(line), origins.size()) - 1].element;
    }
};

class SourceSet {
public:
    int add(std::string path, std::string text, std::vector<LineOrigin> origins = {}, std::string userText = {}) {
        files_.push_back({std::move(path), std::move(text), std::move(origins), std::move(userText)});
        return static_cast<int>(files_.size()) - 1;
    }
    const SourceFile& file(int index) const { return files_.at(static_cast<size_t>(index)); }
    int size() const { return static_cast<int>(files_.size()); }
    // The libraries a TwinCAT .plcproj of the project references (decision 0279).
    void addReferencedLibrary(const std::string& name) {
        if (std::find(libraries_.begin(), libraries_.end(), name) == libraries_.end()) libraries_.push_back(name);
    }
    const std::vector<std::string>& referencedLibraries() const { return libraries_; }
    // A referenced library whose own project folder is given: strun reads it,
    // so it is not missing (decision 0454).
    void dropReferencedLibrary(const std::string& name) { std::erase(libraries_, name); }
    // The namespace of a TwinCAT library project's file: the `<Namespace>` of
    // the reference that names the library, else its `<DefaultNamespace>`
    // (decision 0454); "" for every other file.
    void setLibraryNamespace(int index, std::string nameSpace) {
        if (libraryNamespaces_.size() <= static_cast<size_t>(index)) libraryNamespaces_.resize(static_cast<size_t>(index) + 1);
        libraryNamespaces_[static_cast<size_t>(index)] = std::move(nameSpace);
    }
    const std::string& libraryNamespace(int index) const {
        static const std::string none;
        return index >= 0 && static_cast<size_t>(index) < libraryNamespaces_.size() ? libraryNamespaces_[static_cast<size_t>(index)] : none;
    }
    // `<PinnedGlobalDataType>` names of a .plcproj (decision 0447).
    void addPinnedType(const std::string& name) { pinnedTypes_.push_back(name); }
    const std::vector<std::string>& pinnedTypes() const { return pinnedTypes_; }
    // A file strun wrote from the project's files that is checked as a
    // library file: a declaration of the user's named like one of it replaces
    // it (the global data types of a TwinCAT type system, decision 0447).
    void markProjectLibrary(int index) { projectLibraries_.push_back(index); }
    bool isProjectLibrary(int index) const {
        return std::find(projectLibraries_.begin(), projectLibraries_.end(), index) != projectLibraries_.end();
    }

private:
    std::vector<SourceFile> files_;
    std::vector<std::string> libraries_;
    std::vector<int> projectLibraries_;
    std::vector<std::string> pinnedTypes_;
    std::vector<std::string> libraryNamespaces_;  // by file index
};

class CompileLog {
public:
    // A cap so that a pathological file cannot flood stderr or memory.
    static constexpr size_t kMaxMessages = 500;

    // The code first, given where the diagnostic is raised (decision 0298):
    // the wording never decides it. The returned diagnostic takes notes and help lines.
    Diagnostic& error(diag::Code code, const ast::Loc& loc, std::string message) {
        return add(Severity::Error, code, loc, std::move(message));
    }
    Diagnostic& warning(diag::Code code, const ast::Loc& loc, std::string message) {
        return add(Severity::Warning, code, loc, std::move(message));
    }
    bool hasErrors() const { return errors_ > 0; }
    size_t errorCount() const { return errors_; }
    const std::vector<Diagnostic>& messages() const { return messages_; }
    // Removes the diagnostics `drop` selects (cascades of an earlier error).
    template <class Pred>
    void eraseIf(Pred drop) {
        std::erase_if(messages_, drop);
        errors_ = dropped_ > 0 ? errors_ : static_cast<size_t>(std::count_if(messages_.begin(), messages_.end(), [](const Diagnostic& d) {
            return d.severity == Severity::Error;
        }));
    }
    size_t droppedCount() const { return dropped_; }
    // Lets `f` add notes and help lines to every kept diagnostic.
    template <class F>
    void decorate(F f) {
        for (Diagnostic& d : messages_) f(d);
    }
    // True for the scratch diagnostic a reporter past the cap decorates.
    bool isDropped(const Diagnostic& d) const { return &d == &overflow_; }
    // Removes the messages from position `count` on (a check whose result was discarded).
    void dropFrom(size_t count) {
        if (count >= messages_.size()) return;
        for (size_t i = count; i < messages_.size(); ++i) errors_ -= messages_[i].severity == Severity::Error;
        messages_.resize(count);
    }
    // A diagnostic made before (a cached parse's, another log's) again, code, notes and all.
    Diagnostic& repeat(Diagnostic d) {
        Diagnostic& added = add(d.severity, diag::E0001, d.loc, std::string());
        if (&added != &overflow_) added = std::move(d);
        return added;
    }
    // Appends the messages of `other` (a log filled on another thread), in
    // order and within this log's cap.
    void append(CompileLog&& other) {
        const size_t errors = errors_ + other.errors_;  // add() below counts only the messages other kept
        for (Diagnostic& d : other.messages_) repeat(std::move(d));
        dropped_ += other.dropped_;
        errors_ = errors;
    }

    // FILE:LINE:COL: error: MESSAGE, one per line, in the order reported.
    void print(std::ostream& out, const SourceSet& sources) const {
        for (const auto& m : messages_) {
            const bool known = m.loc.file >= 0 && m.loc.file < sources.size();
            const std::string& path = known ? sources.file(m.loc.file).path : std::string("<unknown>");
            auto [line, col] = known ? sources.file(m.loc.file).original(m.loc.line, m.loc.col) : std::pair<int, int>{m.loc.line, m.loc.col};
            out << path << ':' << (line > 0 ? line : 1) << ':' << (col > 0 ? col : 1)
                << ": " << (m.severity == Severity::Error ? "error" : "warning") << ": " << m.message << '\n';
        }
        if (dropped_ > 0) out << "note: " << dropped_ << " further messages suppressed\n";
    }

private:
    Diagnostic& add(Severity s, diag::Code code, const ast::Loc& loc, std::string message) {
        if (s == Severity::Error) ++errors_;
        if (messages_.size() >= kMaxMessages) {
            ++dropped_;
            overflow_ = Diagnostic{};
            return overflow_;
        }
        Diagnostic d;
        d.severity = s;
        d.loc = loc;
        d.code = diag::text(code);
        d.message = std::move(message);
        messages_.push_back(std::move(d));
        return messages_.back();
    }
    std::vector<Diagnostic> messages_;
    Diagnostic overflow_;  // what a reporter past the cap decorates, never printed
    size_t errors_ = 0;
    size_t dropped_ = 0;
};

}  // namespace strun
