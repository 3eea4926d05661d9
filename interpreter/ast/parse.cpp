// parseFile: source text -> tokens -> parse -> AST, with every problem
// reported to the CompileLog and nothing thrown.
//
// Stages: (1) make the bytes valid UTF-8; (2) scan everything (ast/st_scanner.h,
// then ast/action_keyword.h), reporting the error tokens (unterminated
// comments/strings/pragmas, stray characters) at their exact location;
// (3) refuse pathological nesting before the recursive parser sees it;
// (4) parse with SLL prediction and bail out on the first error, then, only if
// that failed, parse again with full LL and error recovery, so that valid
// files take the fast path and invalid ones get the best messages;
// (5) build the AST. Stages 4 and 5 run on a thread with a large stack; a
// large file that parses cleanly is parsed in two halves on two threads
// (ast/parse_in_halves.h).
#include "interpreter/ast/parse.h"

#include <atomic>
#include <cctype>
#include <exception>
#include <optional>
#include <string_view>

#include <antlr4-runtime.h>

#include "grammar/STLexer.h"
#include "grammar/STParser.h"
#include "interpreter/ast/action_keyword.h"
#include "interpreter/ast/edge_keyword.h"
#include "interpreter/ast/ax_twincat_tokens.h"
#include "interpreter/ast/ast_builder.h"
#include "interpreter/ast/large_stack.h"
#include "interpreter/ast/nesting_guard.h"
#include "interpreter/ast/scanned_tokens.h"
#include "interpreter/ast/st_scanner.h"
#include "interpreter/ast/syntax_errors.h"
#include "interpreter/ast/thread_heap.h"
#include "interpreter/ast/utf8_input.h"
#include "stdlib/number_scan.h"

namespace strun::ast {

namespace {

using L = strun_grammar::STLexer;
using P = strun_grammar::STParser;

// A comment, pragma or string the file ends inside (E0005; other error tokens are E0006).
bool isUnterminated(const antlr4::Token& token) {
    switch (token.getType()) {
        case L::UNTERMINATED_BLOCK_COMMENT: case L::UNTERMINATED_C_COMMENT: case L::UNTERMINATED_PRAGMA:
        case L::UNTERMINATED_STRING: case L::UNTERMINATED_WSTRING:
            return true;
        default:
            return false;
    }
}

std::string lexerErrorMessage(const antlr4::Token& token) {
    switch (token.getType()) {
        case L::UNTERMINATED_BLOCK_COMMENT: return "unterminated comment: '(*' has no matching '*)'";
        case L::UNTERMINATED_C_COMMENT: return "unterminated comment: '/*' has no matching '*/'";
        case L::UNTERMINATED_PRAGMA: return "unterminated pragma: '{' has no matching '}'";
        case L::UNTERMINATED_STRING: return "unterminated string literal: missing closing ' on this line";
        case L::UNTERMINATED_WSTRING: return "unterminated string literal: missing closing \" on this line";
        default: break;
    }
    const std::string text = token.getText();
    const unsigned char first = text.empty() ? 0 : static_cast<unsigned char>(text[0]);
    if (first >= 0x21 && first < 0x7F) return "unexpected character '" + text + "'";
    if (text == "\xEF\xBF\xBD") return "unexpected byte (not valid UTF-8)";
    if (first < 0x80) return "unexpected control character (code " + std::to_string(first) + ")";
    return "unexpected character '" + text + "'";
}

// The scanner's tokens with ACTION kept only where an action declaration
// starts (ast/action_keyword.h).
ScanResult scanWithActionKeyword(std::string_view text) {
    ScanResult scan = scanSource(text, kMaxTokensPerFile);
    resolveActionKeyword(scan.tokens);
    resolveEdgeKeyword(text, scan.tokens);  // `x : BOOL R_EDGE;`
    resolveAxTwinCatForms(text, scan.tokens, &scan.emptyDeclarations);  // OVERRIDE, `END_VAR;`, `{pragma};`, `;;`
    return scan;
}

class FileParser {
public:
    FileParser(const SourceSet& sources, int fileIndex, CompileLog& log, size_t halvesFrom)
        : halvesFrom_(halvesFrom),
          text_(sanitizeUtf8(sources.file(fileIndex).text, &firstInvalidByte_, &invalidBytes_)),
          scan_(scanWithActionKeyword(text_)),
          source_(text_, scan_.tokens),
          reporter_(log, fileIndex),
          log_(log),
          fileIndex_(fileIndex) {}

    CompilationUnit run() {
        warnAboutInvalidUtf8();
        if (!lexWithinLimit()) return emptyUnit();
        reportForeignOperators();
        reportMessagePragmas();
        reportEmptyDeclarations();
        if (!reportLexerErrors()) return emptyUnit();
        if (scan_.tokens.size() >= halvesFrom_)
            if (auto halves = parseInHalves(text_, scan_.tokens, fileIndex_)) return std::move(*halves);
        // Parsed whole: only now the token stream (its views of every
        // token and lookahead tables) and the parser; a file parsed in
        // halves never needs them (decisions 0492, 0493).
        tokens_.emplace(&source_);
        parser_.emplace(&*tokens_);
        parser_->removeErrorListeners();
        // The AST builder reads the contexts' labels only (decision 0159):
        // no terminal node per token, no child lists.
        parser_->setBuildParseTree(false);
        CompilationUnit unit = emptyUnit();
        runWithLargeStack([&] {
            strun_grammar::RuleContextArena::Scope arena(contextArena_);  // the contexts of this parse
            try {
                P::CompilationUnitContext* tree = parse();
                AstBuilder builder(*tokens_, reporter_, fileIndex_);
                unit = builder.build(tree);
            } catch (const std::exception& e) {
                log_.error(diag::E0001, Loc{fileIndex_, 1, 1}, std::string("internal parser error: ") + e.what());
            } catch (...) {
                log_.error(diag::E0001, Loc{fileIndex_, 1, 1}, "internal parser error");
            }
        });
        return unit;
    }

private:
    CompilationUnit emptyUnit() const {
        CompilationUnit unit;
        unit.file = fileIndex_;
        return unit;
    }

    // A Latin-1 file, say, still compiles (its odd bytes are usually in
    // comments or strings), but the user should know that characters changed.
    void warnAboutInvalidUtf8() {
        if (invalidBytes_ == 0) return;
        int line = 1, col = 1;
        for (size_t i = 0; i < firstInvalidByte_ && i < text_.size(); ++i) {
            const unsigned char c = static_cast<unsigned char>(text_[i]);
            if (c == '\n') {
                ++line;
                col = 1;
            } else if ((c & 0xC0) != 0x80) {
                ++col;  // count code points, as the scanner does
            }
        }
        log_.warning(diag::W0006, Loc{fileIndex_, line, col},
                     "the file is not valid UTF-8: " + std::to_string(invalidBytes_) +
                         " byte(s) replaced by U+FFFD, the first here");
    }

    // Past kMaxTokensPerFile tokens (comments and pragmas included) the
    // scanner stopped, so that memory stays bounded: an error, no parse.
    bool lexWithinLimit() {
        if (scan_.overLimit) {
            const ScannedToken& at = scan_.tokens[scan_.tokens.size() - 2];  // the last before EOF
            log_.error(diag::E0007, Loc{fileIndex_, static_cast<int>(at.line), static_cast<int>(at.column) + 1},
                       "the file has more than " + std::to_string(kMaxTokensPerFile) + " tokens (the limit per source file)");
            return false;
        }
        return true;
    }

    // `x : INT;;`: the extra `;` is dropped with a warning (decision 0276).
    void reportEmptyDeclarations() {
        for (std::size_t i : scan_.emptyDeclarations) {
            const ScannedToken& t = scan_.tokens[i];
            log_.warning(diag::W0040, Loc{fileIndex_, static_cast<int>(t.line), static_cast<int>(t.column) + 1},
                         "an empty declaration: this ';' ends nothing and is ignored");
        }
    }

    // The operators of C and Java that ST beginners type (`==`, `!=`, `&&`,
    // `||`, `++`, `+=`, `!`): one message with the ST spelling, before the
    // parser's less helpful one on the same line (one error per line).
    void reportForeignOperators() {
        // The scanner's tokens themselves: no view (with its virtual
        // destructor) per token, no copy of the text unless one matches.
        const std::vector<ScannedToken>& tokens = scan_.tokens;
        auto seenFrom = [&](size_t i) {  // the first token at or after i that the parser (or the error report) sees
            while (i < tokens.size() && tokens[i].channel != antlr4::Token::DEFAULT_CHANNEL && tokens[i].channel != L::ERRORS) ++i;
            return i;
        };
        auto textOf = [&](const ScannedToken* t) { return tokenText(text_, *t); };
        auto is = [&](const ScannedToken* t, size_t type, const char* text = nullptr) {
            return t->type == type && (text == nullptr || textOf(t) == text);
        };
        const ScannedToken* before = nullptr;
        for (size_t i = seenFrom(0), next; i < tokens.size(); before = &tokens[i], i = next) {
            next = seenFrom(i + 1);
            const ScannedToken* a = &tokens[i];
            const ScannedToken* b = next < tokens.size() ? &tokens[next] : nullptr;
            const bool pair = b != nullptr && b->start == stopIndex(*a) + 1;
            auto target = [&] { return before != nullptr && P::isNameToken(before->type) ? std::string(textOf(before)) : "x"; };
            std::string op, help;
            if (pair && is(a, L::EQ) && is(b, L::EQ)) {
                op = "==", help = "compare with a single '=': IF a = b THEN";
            } else if (pair && is(a, L::ERROR_CHAR, "!") && is(b, L::EQ)) {
                op = "!=", help = "'<>' means not equal: IF a <> b THEN";
            } else if (is(a, L::ERROR_CHAR, "!")) {
                op = "!", help = "write NOT: IF NOT done THEN";
            } else if (pair && is(a, L::AMP) && is(b, L::AMP)) {
                op = "&&", help = "write AND: IF a AND b THEN";
            } else if (pair && is(a, L::ERROR_CHAR, "|") && is(b, L::ERROR_CHAR, "|")) {
                op = "||", help = "write OR: IF a OR b THEN";
            } else if (pair && (is(a, L::PLUS) || is(a, L::MINUS)) && b->type == a->type) {
                const std::string sign(textOf(a));
                op = sign + sign, help = "write '" + target() + " := " + target() + " " + sign + " 1;'";
            } else if (pair && (is(a, L::PLUS) || is(a, L::MINUS) || is(a, L::STAR) || is(a, L::SLASH)) && is(b, L::EQ)) {
                const std::string sign(textOf(a));
                op = sign + "=", help = "write '" + target() + " := " + target() + " " + sign + " ...;'";
            } else {
                continue;
            }
            reporter_.report(diag::E0004, a->line, a->column, "ST has no '" + op + "' operator").withHelp(help)
                .spanTo(static_cast<int>(a->line), static_cast<int>(a->column + op.size()) + 1);
            if (pair && op.size() == 2) {  // b is part of the operator
                i = next;
                next = seenFrom(i + 1);
            }
        }
    }

    // {warning 'text'} / {error 'text'}: the keyword in any case, blanks
    // around the keyword and around the quoted text, no quote inside the
    // text. That is what the regular expression
    // ^\{\s*(warning|error)\s+'([^']*)'\s*\}$ matched before; decision 0491
    // scans by hand instead of with <regex>, whose instantiation took seconds
    // of every fresh build.
    static bool parseMessagePragma(std::string_view text, bool& isError, std::string_view& message) {
        auto blank = [](char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; };
        if (text.size() < 2 || text.front() != '{' || text.back() != '}') return false;
        const size_t end = text.size() - 1;  // the closing brace
        size_t i = 1;
        while (i < end && blank(text[i])) ++i;
        auto keyword = [&](std::string_view word) {
            return end - i >= word.size() && stdlib::equalsIgnoreCase(text.substr(i, word.size()), word);
        };
        if (keyword("warning")) {
            isError = false;
            i += 7;
        } else if (keyword("error")) {
            isError = true;
            i += 5;
        } else {
            return false;
        }
        const size_t afterKeyword = i;
        while (i < end && blank(text[i])) ++i;
        if (i == afterKeyword || i >= end || text[i] != '\'') return false;
        const size_t close = text.find('\'', i + 1);
        if (close >= end) return false;
        message = text.substr(i + 1, close - i - 1);
        i = close + 1;
        while (i < end && blank(text[i])) ++i;
        return i == end;
    }

    // {warning 'text'} and {error 'text'} (CODESYS message pragmas): the text
    // as a warning (W0010) or an error (E0010) at the pragma.
    void reportMessagePragmas() {
        for (size_t i = 0; i < scan_.tokens.size(); ++i) {
            if (scan_.tokens[i].channel != L::PRAGMAS) continue;
            const ScannedTokenView view = viewOf(i);
            const ScannedTokenView* t = &view;
            const std::string text = t->getText();
            if (text.size() >= 4 && text[1] == '{' && text[text.size() - 2] == '}') {  // matiec/Beremiz inline C code (0351)
                const Loc at{fileIndex_, static_cast<int>(t->getLine()), static_cast<int>(t->getCharPositionInLine()) + 1};
                log_.warning(diag::W0045, at, "inline C code ({{ ... }}) is not run: strun skips it");
                continue;
            }
            bool isError = false;
            std::string_view message;
            if (text.size() > 4096 || !parseMessagePragma(text, isError, message)) continue;
            const Loc at{fileIndex_, static_cast<int>(t->getLine()), static_cast<int>(t->getCharPositionInLine()) + 1};
            const std::string shown(message);
            Diagnostic& d = isError ? log_.error(diag::E0010, at, shown) : log_.warning(diag::W0010, at, shown);
            if (text.find('\n') == std::string::npos) d.spanTo(at.line, at.col + static_cast<int>(text.size()));
        }
    }

    // Reports error tokens and runs the nesting guard; false if parsing must
    // not go ahead.
    bool reportLexerErrors() {
        for (size_t i = 0; i < scan_.tokens.size(); ++i) {
            if (scan_.tokens[i].channel != L::ERRORS) continue;
            const ScannedTokenView view = viewOf(i);
            const ScannedTokenView* token = &view;
            reporter_.report(isUnterminated(*token) ? diag::E0005 : diag::E0006, token->getLine(),
                             token->getCharPositionInLine(), lexerErrorMessage(*token), token->getType() != L::ERROR_CHAR);
            // The statement an unterminated string cut off ends on the next line: one error, not two.
            if (token->getType() == L::UNTERMINATED_STRING || token->getType() == L::UNTERMINATED_WSTRING)
                reporter_.markLine(token->getLine() + 1);
            // An unterminated comment or pragma swallowed the rest of the file: what the
            // parser then misses (END_PROGRAM, ...) is its consequence, not news.
            if (token->getType() == L::UNTERMINATED_BLOCK_COMMENT || token->getType() == L::UNTERMINATED_C_COMMENT ||
                token->getType() == L::UNTERMINATED_PRAGMA)
                reporter_.silence();
        }
        if (auto violation = findExcessiveNesting(scan_.tokens)) {
            const ScannedToken& at = scan_.tokens[violation->token];
            log_.error(diag::E0007, Loc{fileIndex_, static_cast<int>(at.line), static_cast<int>(at.column) + 1},
                       "syntax error: " + violation->message);
            return false;
        }
        return true;
    }

    // Token i as the parser would see it, made when a report needs it.
    ScannedTokenView viewOf(size_t i) { return ScannedTokenView(scan_.tokens[i], i, &source_); }

    P::CompilationUnitContext* parse() {
        auto* simulator = parser_->getInterpreter<antlr4::atn::ParserATNSimulator>();
        simulator->setPredictionMode(antlr4::atn::PredictionMode::SLL);
        parser_->setErrorHandler(std::make_shared<antlr4::BailErrorStrategy>());
        try {
            return parser_->compilationUnit();
        } catch (const antlr4::ParseCancellationException&) {
            // Not SLL-parseable as is: a syntax error, or (rarely) a construct
            // that needs full-context prediction. Parse again properly.
        }
        tokens_->seek(0);
        parser_->reset();
        parser_->setBuildParseTree(false);
        simulator->setPredictionMode(antlr4::atn::PredictionMode::LL);
        parser_->setErrorHandler(std::make_shared<FriendlyErrorStrategy>(&reporter_));
        parser_->addErrorListener(&reporter_);
        return parser_->compilationUnit();
    }

    size_t halvesFrom_;
    size_t firstInvalidByte_ = 0;
    size_t invalidBytes_ = 0;
    std::string text_;
    ScanResult scan_;
    ScannedTokenSource source_;
    std::optional<ScannedTokenStream> tokens_;      // made when the file is parsed whole
    strun_grammar::RuleContextArena contextArena_;  // outlives parser_, which deletes the contexts
    std::optional<P> parser_;                      // made when the file is parsed whole
    SyntaxErrorReporter reporter_;
    CompileLog& log_;
    int fileIndex_;
};

}  // namespace

CompilationUnit parseFile(const SourceSet& sources, int fileIndex, CompileLog& log, size_t halvesFrom) {
    try {
        FileParser parser(sources, fileIndex, log, halvesFrom);
        return parser.run();
    } catch (const std::exception& e) {
        log.error(diag::E0001, Loc{fileIndex, 1, 1}, std::string("internal parser error: ") + e.what());
    } catch (...) {
        log.error(diag::E0001, Loc{fileIndex, 1, 1}, "internal parser error");
    }
    CompilationUnit unit;
    unit.file = fileIndex;
    return unit;
}

std::vector<CompilationUnit> parseFiles(const SourceSet& sources, const std::vector<int>& files, CompileLog& log) {
    std::vector<CompilationUnit> units(files.size());
    if (files.size() < 2) {
        for (size_t i = 0; i < files.size(); ++i) units[i] = parseFile(sources, files[i], log);
        return units;
    }
    // Each worker takes the next file not yet taken; each file has its own
    // log until both are done.
    std::vector<CompileLog> logs(files.size());
    std::atomic<size_t> next{0};
    std::size_t sourceBytes = 0;
    for (int f : files) sourceBytes += sources.file(f).text.size();
    auto worker = [&] {
        // Each worker builds about half of the trees, in its thread's arena (decision 0494).
        growThisThreadsHeap(sourceBytes / 2 * kTreeBytesPerSourceByte);
        for (size_t i = next++; i < files.size(); i = next++) units[i] = parseFile(sources, files[i], logs[i]);
    };
    runInParallelWithLargeStacks(worker, worker);
    for (CompileLog& fileLog : logs) log.append(std::move(fileLog));
    return units;
}

}  // namespace strun::ast
