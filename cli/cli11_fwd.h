// The CLI11 classes that the cli/ headers name, declared without CLI11
// itself: <CLI/CLI.hpp> costs about 4 s of compile time in every file that
// includes it (parsing, and its validators and formatters compiled again),
// so only the files that register options or parse include it (issue 28).
#pragma once

namespace CLI {
class App;
class Validator;
class ParseError;
}  // namespace CLI
