# Run after ANTLR generates the parser:
#   cmake -DPARSER_CPP=<STParser.cpp> -DPARSER_H=<STParser.h> -P typed_atn.cmake
#
# The generated parser builds its ATN at static initialisation with ANTLR's
# ATNDeserializer, which asks dynamic_cast about every state and transition:
# half of a one-line `strun run`. It uses grammar/typed_atn_deserializer.h
# instead (decision 0468), and the header gets a read-only accessor to the
# serialized ATN so that tests/unit/ast/typed_atn_test.cpp can compare the
# two deserializers' results.
file(READ "${PARSER_CPP}" text)
string(FIND "${text}" "  atn::ATNDeserializer deserializer;" at)
if(at EQUAL -1)
  message(FATAL_ERROR "typed_atn.cmake: the generated parser no longer declares 'atn::ATNDeserializer deserializer;'")
endif()
string(REPLACE "  atn::ATNDeserializer deserializer;" "  strun_grammar::TypedAtnDeserializer deserializer;" text "${text}")
file(WRITE "${PARSER_CPP}" "#include \"grammar/typed_atn_deserializer.h\"\n${text}")

file(READ "${PARSER_H}" header)
string(FIND "${header}" "  struct Initializer {" at)
if(at EQUAL -1)
  message(FATAL_ERROR "typed_atn.cmake: the generated parser header no longer has its Initializer")
endif()
string(REPLACE "  struct Initializer {"
  "public:\n  static const std::vector<uint16_t> &serializedATN() { return _serializedATN; }\nprivate:\n  struct Initializer {"
  header "${header}")
file(WRITE "${PARSER_H}" "${header}")
