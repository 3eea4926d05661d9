#include "interpreter/ast/parse_in_halves.h"

#include <antlr4-runtime.h>

#include "grammar/STLexer.h"
#include "grammar/STParser.h"
#include "interpreter/ast/ast_builder.h"
#include "interpreter/ast/large_stack.h"
#include "interpreter/ast/scanned_tokens.h"
#include "interpreter/ast/syntax_errors.h"
#include "interpreter/ast/thread_heap.h"

namespace strun::ast {

namespace {

using L = strun_grammar::STLexer;
using P = strun_grammar::STParser;

bool startsDeclaration(std::size_t type) {
    switch (type) {
        case L::PROGRAM: case L::FUNCTION: case L::FUNCTION_BLOCK: case L::INTERFACE: case L::TYPE: return true;
        default: return false;
    }
}

bool endsDeclaration(std::size_t type) {
    switch (type) {
        case L::END_PROGRAM: case L::END_FUNCTION: case L::END_FUNCTION_BLOCK: case L::END_INTERFACE: case L::END_TYPE:
            return true;
        default: return false;
    }
}

// The index of the last token of the first half: an END_PROGRAM, END_TYPE,
// ... outside any NAMESPACE whose next token starts a PROGRAM, FUNCTION,
// FUNCTION_BLOCK, INTERFACE or TYPE (not an ACTION or METHOD, which belong
// to the declaration before them), the first such at or after the middle.
std::optional<std::size_t> splitPoint(const std::vector<ScannedToken>& tokens) {
    std::vector<std::size_t> onChannel;  // default-channel tokens, EOF excluded
    onChannel.reserve(tokens.size());
    for (std::size_t i = 0; i + 1 < tokens.size(); ++i)
        if (tokens[i].channel == antlr4::Token::DEFAULT_CHANNEL) onChannel.push_back(i);
    int namespaceDepth = 0;
    for (std::size_t k = 0; k + 1 < onChannel.size(); ++k) {
        const ScannedToken& token = tokens[onChannel[k]];
        if (token.type == L::NAMESPACE) ++namespaceDepth;
        if (token.type == L::END_NAMESPACE) --namespaceDepth;
        if (onChannel[k] < tokens.size() / 2 || namespaceDepth != 0) continue;
        if (endsDeclaration(token.type) && startsDeclaration(tokens[onChannel[k + 1]].type)) return onChannel[k];
    }
    return std::nullopt;
}

struct Half {
    std::span<const ScannedToken> tokens;  // the file's, not copied (decision 0493)
    const ScannedToken* eof = nullptr;     // the first half's: where the second starts
    CompilationUnit unit;
    bool clean = false;
};

// Parses one half. The two parsers share the generated parser's prediction
// tables (DFA), as ANTLR intends: its 4.9 runtime guards them with locks
// shared by all parsers (ATNSimulator::_stateLock and _edgeLock are static).
void parseHalf(std::string_view text, Half& half, int fileIndex) {
    // The tree is built in the arena of the thread that parses the half (decision 0494).
    growThisThreadsHeap(half.tokens.size() * kTreeBytesPerToken);
    try {
        ScannedTokenSource source(text, half.tokens, half.eof);
        ScannedTokenStream stream(&source);
        strun_grammar::RuleContextArena arena;  // outlives the parser, which deletes the contexts
        strun_grammar::RuleContextArena::Scope scope(arena);
        P parser(&stream);
        parser.getInterpreter<antlr4::atn::ParserATNSimulator>()->setPredictionMode(antlr4::atn::PredictionMode::SLL);
        parser.removeErrorListeners();
        parser.setBuildParseTree(false);
        parser.setErrorHandler(std::make_shared<antlr4::BailErrorStrategy>());
        P::CompilationUnitContext* tree = parser.compilationUnit();
        CompileLog log;
        SyntaxErrorReporter reporter(log, fileIndex);
        AstBuilder builder(stream, reporter, fileIndex);
        half.unit = builder.build(tree);
        half.clean = log.messages().empty();
    } catch (...) {
        half.clean = false;  // a syntax error (ParseCancellationException) or anything else: parse whole
    }
}

template <typename T>
void append(std::vector<T>& to, std::vector<T>& from) {
    for (T& item : from) to.push_back(std::move(item));
}

}  // namespace

std::optional<CompilationUnit> parseInHalves(std::string_view text, const std::vector<ScannedToken>& tokens, int fileIndex) {
    const std::optional<std::size_t> split = splitPoint(tokens);
    if (!split) return std::nullopt;
    Half first, second;
    first.tokens = std::span<const ScannedToken>(tokens).first(*split + 1);
    ScannedToken eof = tokens.back();  // an empty EOF where the second half starts
    const ScannedToken& next = tokens[*split + 1];
    eof.start = next.start;
    eof.stop = next.start - 1;
    eof.line = next.line;
    eof.column = next.column;
    eof.channel = antlr4::Token::DEFAULT_CHANNEL;
    first.eof = &eof;
    second.tokens = std::span<const ScannedToken>(tokens).subspan(*split + 1);
    runInParallelWithLargeStacks([&] { parseHalf(text, first, fileIndex); }, [&] { parseHalf(text, second, fileIndex); });
    if (!first.clean || !second.clean) return std::nullopt;
    CompilationUnit unit = std::move(first.unit);
    unit.file = fileIndex;
    append(unit.pous, second.unit.pous);
    append(unit.types, second.unit.types);
    append(unit.globals, second.unit.globals);
    append(unit.configurations, second.unit.configurations);
    append(unit.usings, second.unit.usings);
    return unit;
}

}  // namespace strun::ast
