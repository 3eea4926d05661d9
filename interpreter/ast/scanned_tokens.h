// The scanner's tokens (ast/st_scanner.h) as the ANTLR token source the
// generated parser reads, over a character stream whose indexes are byte
// offsets into the UTF-8 source (the text of a token or of a range of tokens
// is a slice of the source, with no conversion).
#pragma once

#include <memory>
#include <string>
#include <span>
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

class ScannedTokenSource;

// ANTLR's stop index of a scanned token. EOF is empty: it stops before it
// starts, as ANTLR's lexers make it (and as a size_t, also at offset 0).
inline size_t stopIndex(const ScannedToken& token) {
    return token.type == antlr4::Token::EOF ? static_cast<size_t>(token.start) - 1 : token.stop;
}

// The text of a scanned token of `text`, as ANTLR's getText() gives it
// ("<EOF>" for EOF).
std::string_view tokenText(std::string_view text, const ScannedToken& token);

// A scanned token as the parser sees it: a view of the ScannedToken and of
// the source text. The stream keeps all of them in one array (one
// allocation per file instead of a CommonToken per token, which was a
// tenth of the parse with its destruction).
class ScannedTokenView final : public antlr4::Token {
public:
    ScannedTokenView(const ScannedToken& token, size_t index, ScannedTokenSource* source)
        : token_(&token), index_(index), source_(source) {}
    std::string getText() const override;
    size_t getType() const override { return token_->type; }
    size_t getLine() const override { return token_->line; }
    size_t getCharPositionInLine() const override { return token_->column; }
    size_t getChannel() const override { return token_->channel; }
    size_t getTokenIndex() const override { return index_; }
    size_t getStartIndex() const override { return token_->start; }
    size_t getStopIndex() const override { return stopIndex(*token_); }
    antlr4::TokenSource* getTokenSource() const override;
    antlr4::CharStream* getInputStream() const override;
    std::string toString() const override;

private:
    const ScannedToken* token_;
    size_t index_;
    ScannedTokenSource* source_;
};

class ScannedTokenSource : public antlr4::TokenSource {
public:
    // `text` and `scanned` must outlive this source; `scanned` ends with its
    // EOF token, or `eof` is that token (the first half of a file parsed in
    // halves, decision 0493: no copy of the half's tokens).
    ScannedTokenSource(std::string_view text, std::span<const ScannedToken> scanned, const ScannedToken* eof = nullptr);
    // For ANTLR's generic use; the parser's stream reads views() instead.
    std::unique_ptr<antlr4::Token> nextToken() override;
    size_t size() const { return scanned_.size() + (eof_ ? 1 : 0); }
    const ScannedToken& token(size_t i) const { return i < scanned_.size() ? scanned_[i] : *eof_; }
    std::string_view text() const { return text_; }
    size_t getLine() const override;
    size_t getCharPositionInLine() override;
    antlr4::CharStream* getInputStream() override { return &stream_; }
    std::string getSourceName() override { return stream_.getSourceName(); }
    antlr4::TokenFactory<antlr4::CommonToken>* getTokenFactory() override {
        return antlr4::CommonTokenFactory::DEFAULT.get();
    }

private:
    std::string_view text_;
    Utf8SourceStream stream_;
    std::span<const ScannedToken> scanned_;
    const ScannedToken* eof_;
    size_t next_ = 0;
};

// The token stream the parser reads: the scanned tokens as views, all
// fetched when it is made, without the per-token virtual call and dynamic
// cast of the runtime's generic fetch. ANTLR's BufferedTokenStream holds
// tokens by unique_ptr; here they point into views_, and the destructor
// releases them before the base class would delete them.
//
// Lookahead (LT, LA, LB) and consume() give the results of
// CommonTokenStream's, edge cases included, from two tables of the next
// and previous default-channel token of each position instead of a walk
// over the hidden tokens with a bounds check per step: the parser asks
// for the next token several times per token (decision 0159).
class ScannedTokenStream : public antlr4::CommonTokenStream {
public:
    explicit ScannedTokenStream(ScannedTokenSource* source);
    ~ScannedTokenStream() override;
    ScannedTokenStream(const ScannedTokenStream&) = delete;
    ScannedTokenStream& operator=(const ScannedTokenStream&) = delete;

    // Every token, hidden ones included, in order (what getTokens() copies).
    std::vector<ScannedTokenView>& views() { return views_; }

    antlr4::Token* LT(ssize_t k) override;
    size_t LA(ssize_t i) override;
    void consume() override;

protected:
    size_t fetch(size_t n) override;
    antlr4::Token* LB(size_t k) override;

private:
    // The position of the token LT(k) returns, or -1 where it returns null.
    ssize_t lookahead(ssize_t k) const;

    std::vector<ScannedTokenView> views_;
    std::vector<uint32_t> nextOnChannel_;      // BufferedTokenStream::nextTokenOnChannel(i, 0)
    std::vector<int32_t> previousOnChannel_;   // BufferedTokenStream::previousTokenOnChannel(i, 0), -1 for none
};

}  // namespace strun::ast
