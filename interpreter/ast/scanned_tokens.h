// The scanner's tokens (ast/st_scanner.h) as the ANTLR token source the
// generated parser reads, over a character stream whose indexes are byte
// offsets into the UTF-8 source (the text of a token or of a range of tokens
// is a slice of the source, with no conversion).
#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include <antlr4-runtime.h>

#include "interpreter/ast/st_scanner.h"

namespace strun::ast {

// Read-only view of UTF-8 text for ANTLR: getText(a..b) is bytes a..b.
// Consuming it character by character is not supported (nothing here lexes
// with it); LA and consume step over bytes.
class Utf8SourceStream : public antlr4::CharStream {
public:
    explicit Utf8SourceStream(std::string_view text) : text_(text) {}
    std::string getText(const antlr4::misc::Interval& interval) override;
    std::string toString() const override { return std::string(text_); }
    void consume() override;
    size_t LA(ssize_t i) override;
    ssize_t mark() override { return -1; }
    void release(ssize_t) override {}
    size_t index() override { return position_; }
    void seek(size_t index) override { position_ = std::min(index, text_.size()); }
    size_t size() override { return text_.size(); }
    std::string getSourceName() const override { return "<source>"; }

private:
    std::string_view text_;
    size_t position_ = 0;
};

class ScannedTokenSource : public antlr4::TokenSource {
public:
    // `text` must outlive this source; `scanned` ends with its EOF token.
    ScannedTokenSource(std::string_view text, const std::vector<ScannedToken>& scanned);
    std::unique_ptr<antlr4::Token> nextToken() override { return next(0); }
    // The next token as a CommonToken, its index in the stream set.
    std::unique_ptr<antlr4::CommonToken> next(size_t tokenIndex);
    size_t count() const { return scanned_.size(); }
    size_t getLine() const override;
    size_t getCharPositionInLine() override;
    antlr4::CharStream* getInputStream() override { return &stream_; }
    std::string getSourceName() override { return stream_.getSourceName(); }
    antlr4::TokenFactory<antlr4::CommonToken>* getTokenFactory() override {
        return antlr4::CommonTokenFactory::DEFAULT.get();
    }

private:
    Utf8SourceStream stream_;
    const std::vector<ScannedToken>& scanned_;
    size_t next_ = 0;
};

// The token stream the parser reads: fills itself from a ScannedTokenSource
// without the per-token virtual call and dynamic cast of the runtime's
// generic fetch (a twentieth of `strun check` on a large file).
class ScannedTokenStream : public antlr4::CommonTokenStream {
public:
    explicit ScannedTokenStream(ScannedTokenSource* source) : antlr4::CommonTokenStream(source), source_(source) {}

protected:
    size_t fetch(size_t n) override;

private:
    ScannedTokenSource* source_;
};

}  // namespace strun::ast
