#include "interpreter/ast/scanned_tokens.h"

namespace strun::ast {

std::string Utf8SourceStream::getText(const antlr4::misc::Interval& interval) {
    if (interval.a < 0 || interval.b < interval.a || static_cast<size_t>(interval.a) >= text_.size()) return "";
    const size_t stop = std::min(static_cast<size_t>(interval.b), text_.size() - 1);
    return std::string(text_.substr(static_cast<size_t>(interval.a), stop + 1 - static_cast<size_t>(interval.a)));
}

void Utf8SourceStream::consume() {
    if (position_ < text_.size()) ++position_;
}

size_t Utf8SourceStream::LA(ssize_t i) {
    if (i == 0) return 0;
    const ssize_t at = i > 0 ? static_cast<ssize_t>(position_) + i - 1 : static_cast<ssize_t>(position_) + i;
    if (at < 0 || static_cast<size_t>(at) >= text_.size()) return antlr4::Token::EOF;
    return static_cast<unsigned char>(text_[static_cast<size_t>(at)]);
}

std::string_view tokenText(std::string_view text, const ScannedToken& token) {
    if (token.type == antlr4::Token::EOF || token.start >= text.size()) return "<EOF>";  // as CommonToken
    if (token.stop < token.start) return {};
    return text.substr(token.start, std::min<size_t>(token.stop, text.size() - 1) + 1 - token.start);
}

std::string ScannedTokenView::getText() const { return std::string(tokenText(source_->text(), *token_)); }

antlr4::TokenSource* ScannedTokenView::getTokenSource() const { return source_; }

antlr4::CharStream* ScannedTokenView::getInputStream() const { return source_->getInputStream(); }

std::string ScannedTokenView::toString() const {
    return "[@" + std::to_string(index_) + "," + std::to_string(getStartIndex()) + ":" +
           std::to_string(static_cast<ssize_t>(getStopIndex())) + "='" + getText() + "',<" + std::to_string(getType()) +
           ">," + std::to_string(getLine()) + ":" + std::to_string(getCharPositionInLine()) + "]";
}

ScannedTokenSource::ScannedTokenSource(std::string_view text, std::span<const ScannedToken> scanned, const ScannedToken* eof)
    : text_(text), stream_(text), scanned_(scanned), eof_(eof) {}

std::unique_ptr<antlr4::Token> ScannedTokenSource::nextToken() {
    // Past the end the EOF token again, as a lexer would.
    const ScannedToken& t = token(std::min(next_, size() - 1));
    if (next_ < size()) ++next_;
    auto token = std::make_unique<antlr4::CommonToken>(std::make_pair(this, &stream_), t.type, t.channel, t.start, stopIndex(t));
    token->setLine(t.line);
    token->setCharPositionInLine(t.column);
    return token;
}

size_t ScannedTokenSource::getLine() const {
    return token(std::min(next_, size() - 1)).line;
}

size_t ScannedTokenSource::getCharPositionInLine() {
    return token(std::min(next_, size() - 1)).column;
}

ScannedTokenStream::ScannedTokenStream(ScannedTokenSource* source) : antlr4::CommonTokenStream(source) {
    const size_t n = source->size();
    views_.reserve(n);  // never reallocated: _tokens points into it
    for (size_t i = 0; i < n; ++i) views_.emplace_back(source->token(i), i, source);
    fill();
    auto stopsHere = [&](size_t i) {
        return views_[i].getChannel() == antlr4::Token::DEFAULT_CHANNEL || views_[i].getType() == antlr4::Token::EOF;
    };
    nextOnChannel_.resize(n);
    previousOnChannel_.resize(n);
    for (size_t i = n; i-- > 0;)  // the last token is EOF, where the search stops
        nextOnChannel_[i] = static_cast<uint32_t>(stopsHere(i) || i + 1 == n ? i : nextOnChannel_[i + 1]);
    for (size_t i = 0; i < n; ++i)
        previousOnChannel_[i] = stopsHere(i) ? static_cast<int32_t>(i) : i == 0 ? -1 : previousOnChannel_[i - 1];
}

ssize_t ScannedTokenStream::lookahead(ssize_t k) const {
    const size_t n = views_.size();
    if (k == 0 || n == 0) return -1;
    size_t i = _p;
    if (k > 0) {
        for (ssize_t step = 1; step < k; ++step)
            if (i + 1 < n) i = nextOnChannel_[i + 1];
        return static_cast<ssize_t>(i);
    }
    const size_t back = static_cast<size_t>(-k);
    if (back > _p) return -1;
    // As CommonTokenStream::LB: a search from before position 0 (its index
    // wraps around as a size_t) lands on the last token, EOF.
    ssize_t at = static_cast<ssize_t>(i);
    for (size_t step = 0; step < back; ++step) at = at <= 0 ? static_cast<ssize_t>(n - 1) : previousOnChannel_[at - 1];
    return at;
}

antlr4::Token* ScannedTokenStream::LT(ssize_t k) {
    const ssize_t i = lookahead(k);
    return i < 0 ? nullptr : &views_[static_cast<size_t>(i)];
}

antlr4::Token* ScannedTokenStream::LB(size_t k) { return LT(-static_cast<ssize_t>(k)); }

size_t ScannedTokenStream::LA(ssize_t k) {
    const ssize_t i = lookahead(k);
    if (i < 0) throw antlr4::IllegalStateException("no token at lookahead 0");  // the base dereferences null here
    return views_[static_cast<size_t>(i)].getType();
}

void ScannedTokenStream::consume() {
    if (_p + 1 >= views_.size() && LA(1) == antlr4::Token::EOF) throw antlr4::IllegalStateException("cannot consume EOF");
    if (_p + 1 < views_.size()) _p = nextOnChannel_[_p + 1];
}

ScannedTokenStream::~ScannedTokenStream() {
    for (auto& token : _tokens) (void)token.release();  // owned by views_
}

size_t ScannedTokenStream::fetch(size_t n) {
    if (_fetchedEOF) return 0;
    if (_tokens.empty()) _tokens.reserve(views_.size());
    size_t i = 0;
    while (i < n && _tokens.size() < views_.size()) {
        ScannedTokenView& view = views_[_tokens.size()];
        _tokens.emplace_back(&view);
        ++i;
        if (view.getType() == antlr4::Token::EOF) {
            _fetchedEOF = true;
            break;
        }
    }
    return i;
}

}  // namespace strun::ast
