# Run after ANTLR generates the parser: cmake -DPARSER_CPP=<STParser.cpp> -P static_context_casts.cmake
#
# The generated code stores every label through
# `dynamic_cast<XContext *>(_localctx)`, where _localctx is the XContext the
# same function has just made (a labelled alternative's context is held as
# its rule's base class). A static_cast is exact there, and GCC's
# dynamic_cast compares type names with strcmp at every level of the class
# hierarchy: 2 % of `strun check` (decision 0159).
file(READ "${PARSER_CPP}" text)
string(REGEX REPLACE "dynamic_cast<([A-Za-z]+Context) \\*>\\(_localctx\\)" "static_cast<\\1 *>(_localctx)" text "${text}")
file(WRITE "${PARSER_CPP}" "${text}")
