// IEC 61131-3 (3rd edition) Structured Text tokens, plus the common CODESYS
// extensions: the definition of every token type the parser reads.
//
// strun does not run the lexer generated from this file: it runs the scanner
// of interpreter/ast/st_scanner.cpp, which follows these rules (longest match,
// the earlier rule on a tie) and is tested against the generated lexer on
// every source of the repository and on generated input
// (tests/unit/ast/scanner_equivalence_test.cpp, decision 0157). A change here
// is a change there.
//
// Channels: comments and whitespace are skipped (nothing reads them, and a
// large file has millions); `{...}` pragmas go to PRAGMAS so the
// AST builder can attach them to the declaration they precede; malformed input
// (unterminated comments/strings/pragmas, stray characters) becomes tokens on
// the ERRORS channel, which parse.cpp reports with their exact location, so
// lexing itself never fails. Keywords are case-insensitive.
lexer grammar STLexer;

channels { PRAGMAS, ERRORS }

// Token types without a rule of their own: UNTERMINATED_BLOCK_COMMENT is
// produced by the BLOCK_COMMENT action, the keywords by the scanner from the
// words IDENTIFIER matches (see the keywords section below).
tokens {
    UNTERMINATED_BLOCK_COMMENT,
    PROGRAM,
    END_PROGRAM,
    FUNCTION,
    END_FUNCTION,
    FUNCTION_BLOCK,
    END_FUNCTION_BLOCK,
    METHOD,
    END_METHOD,
    END_ACTION,
    ACTION,
    PROPERTY,
    END_PROPERTY,
    INTERFACE,
    END_INTERFACE,
    NAMESPACE,
    END_NAMESPACE,
    CLASS,
    END_CLASS,
    USING,
    TYPE,
    END_TYPE,
    STRUCT,
    END_STRUCT,
    UNION,
    END_UNION,
    ARRAY,
    OF,
    STRING,
    WSTRING,
    POINTER,
    REF_TO,
    REFERENCE,
    TO,
    EXTENDS,
    IMPLEMENTS,
    ABSTRACT,
    FINAL,
    PUBLIC,
    PRIVATE,
    PROTECTED,
    INTERNAL,
    OVERRIDE,   // only among a METHOD's modifiers (ast/ax_twincat_tokens.h)
    THIS,
    SUPER,
    END_GET,
    END_SET,
    GET,
    SET,
    VAR,
    VAR_INPUT,
    VAR_OUTPUT,
    VAR_IN_OUT,
    VAR_TEMP,
    VAR_STAT,
    VAR_INST,
    VAR_GENERIC,
    VAR_GLOBAL,
    VAR_EXTERNAL,
    VAR_ACCESS,
    VAR_CONFIG,
    END_VAR,
    CONSTANT,
    RETAIN,
    NON_RETAIN,
    PERSISTENT,
    AT,
    CONFIGURATION,
    END_CONFIGURATION,
    RESOURCE,
    END_RESOURCE,
    TASK,
    ON,
    WITH,
    READ_ONLY,
    READ_WRITE,
    R_EDGE,
    F_EDGE,
    IF,
    THEN,
    ELSIF,
    ELSE,
    END_IF,
    CASE,
    END_CASE,
    FOR,
    BY,
    DO,
    END_FOR,
    WHILE,
    END_WHILE,
    REPEAT,
    UNTIL,
    END_REPEAT,
    EXIT,
    CONTINUE,
    RETURN,
    JMP,
    AND_THEN,
    OR_ELSE,
    AND,
    OR,
    XOR,
    NOT,
    MOD,
    TRUE,
    FALSE
}

@members {
  void consumeNestedCommentBody() {
    auto* sim = getInterpreter<antlr4::atn::LexerATNSimulator>();
    int depth = 1;
    for (;;) {
      size_t c = _input->LA(1);
      if (c == antlr4::Token::EOF) {
        setType(UNTERMINATED_BLOCK_COMMENT);
        setChannel(ERRORS);
        return;
      }
      size_t next = _input->LA(2);
      if (c == '(' && next == '*') {
        sim->consume(_input); sim->consume(_input); ++depth;
      } else if (c == '*' && next == ')') {
        sim->consume(_input); sim->consume(_input);
        if (--depth == 0) { skip(); return; }
      } else {
        sim->consume(_input);
      }
    }
  }
}

// ------------------------------------------------------------------ trivia
WS            : [ \t\r\n\f\u000B]+ -> skip;
// (* ... *) comments nest. Nesting cannot be expressed with a regular rule
// that is also longest-match safe, so the rule matches the opener and the
// action consumes the rest; an unterminated one runs to the end of the file and
// becomes an UNTERMINATED_BLOCK_COMMENT token located at its opening.
BLOCK_COMMENT : '(*' { consumeNestedCommentBody(); };
C_COMMENT     : '/*' .*? '*/' -> skip;
UNTERMINATED_C_COMMENT : '/*' ( ~[*] | '*'+ ~[/*] )* '*'* EOF -> channel(ERRORS);
LINE_COMMENT  : '//' ~[\r\n]* -> skip;
// `{{ ... }}`: matiec/Beremiz inline C code, whose own braces nest: it ends at
// the first `}}` (the longer match wins over `{...}`; decision 0351).
PRAGMA        : ( '{{' .*? '}}' | '{' ~[}]* '}' ) -> channel(PRAGMAS);
UNTERMINATED_PRAGMA : '{' ~[}]* EOF -> channel(ERRORS);

// ------------------------------------------------------------------ literals
// Time and date literals come before TYPED_LITERAL: for the same prefix the
// longer (complete) match wins, and on a tie the earlier rule.
DURATION_LITERAL
    : (T | T I M E | L T | L T I M E) '#' [ \t]* ('+' | '-')? DURATION_PART+  // `T# 30ms`: matiec's T# is a token of its own (decision 0357)
    ;
DATE_LITERAL
    : (D | D A T E | L D | L D A T E) '#' DATE_VALUE
    ;
TOD_LITERAL
    : (T O D | T I M E '_' O F '_' D A Y | L T O D | L T I M E '_' O F '_' D A Y) '#' TOD_VALUE
    ;
DT_LITERAL
    : (D T | D A T E '_' A N D '_' T I M E | L D T | L D A T E '_' A N D '_' T I M E) '#' DATE_VALUE '-' TOD_VALUE
    ;
// TYPE#value, e.g. INT#-5, WORD#16#FFFF, REAL#1.0, BOOL#TRUE, Color#Red, STRING#'x'
TYPED_LITERAL
    : IDENT_FRAG '#' ( ('+' | '-')? (DEC_INT | BASED_INT | REAL_FRAG) | IDENT_FRAG | SQ_STRING | DQ_STRING )
    ;
BASED_INTEGER : BASED_INT;
REAL_LITERAL  : REAL_FRAG;
INTEGER       : DEC_INT;
STRING_LITERAL  : SQ_STRING;
WSTRING_LITERAL : DQ_STRING;
// A string without its closing quote stops at the end of the line.
UNTERMINATED_STRING : '\'' ( ~['$\r\n] | '$' ~[\r\n] )* '$'? -> channel(ERRORS);
UNTERMINATED_WSTRING : '"' ( ~["$\r\n] | '$' ~[\r\n] )* '$'? -> channel(ERRORS);

// %IX0.0, %QW2, %MD10, %I*, %Q*; %S11, %SW30 (system bits and words of a target that has them)
DIRECT_ADDRESS : '%' (I | Q | M | S) (X | B | W | D | L)? ( [0-9]+ ('.' [0-9]+)* | '*' );
// x.%X3 (partial access of a bit string)
PARTIAL_ACCESS : '%' (X | B | W | D | L) [0-9]+;

// Underscores between digits, also several (`16#7f_ff__ff_ff`: TwinCAT accepts it).
fragment DEC_INT   : [0-9] ('_'* [0-9])*;
fragment BASED_INT : ('2' | '8' | '10' | '16') '#' '_'? [0-9a-fA-F] ('_'* [0-9a-fA-F])*;
fragment REAL_FRAG : DEC_INT '.' DEC_INT EXPONENT? | DEC_INT EXPONENT;
fragment EXPONENT  : E ('+' | '-')? DEC_INT;
fragment SQ_STRING : '\'' ( ~['$\r\n] | '$' ~[\r\n] )* '\'';
fragment DQ_STRING : '"' ( ~["$\r\n] | '$' ~[\r\n] )* '"';
fragment DURATION_PART : [0-9] [0-9_]* ('.' [0-9]+)? (D | H | M | S | M S | U S | N S) '_'?;
fragment DATE_VALUE : [0-9]+ '-' [0-9]+ '-' [0-9]+;
fragment TOD_VALUE  : [0-9]+ ':' [0-9]+ (':' [0-9]+ ('.' [0-9]+)?)?;

// ------------------------------------------------------------------ keywords
// Keywords are words the IDENTIFIER rule matches; the scanner gives them
// their token type from its table (keywordOrIdentifier in
// interpreter/ast/st_scanner.cpp), so this lexer reports them as IDENTIFIER.
// GET, SET, TASK, ON, WITH, READ_ONLY, READ_WRITE are soft keywords: the
// parser also accepts them as names (SET is an input of the standard RS block).
// R_EDGE and F_EDGE are names everywhere except after `: TYPE` in a
// declaration (interpreter/ast/edge_keyword.h).

// ------------------------------------------------------------------ names
// Letters, digits and underscores. IEC forbids double and trailing underscores,
// CODESYS does not (its operators __NEW, __ISVALIDREF use them): accepted here.
IDENTIFIER : IDENT_FRAG;
fragment IDENT_FRAG : [A-Za-z_] [A-Za-z0-9_]*;

// ------------------------------------------------------------------ operators
ASSIGN     : ':=';
ARROW      : '=>';
TRY_ASSIGN : '?=';
DOTDOT     : '..';
POW        : '**';
LE         : '<=';
GE         : '>=';
NE         : '<>';
LT_OP      : '<';
GT_OP      : '>';
EQ         : '=';
PLUS       : '+';
MINUS      : '-';
STAR       : '*';
SLASH      : '/';
AMP        : '&';
CARET      : '^';
DOT        : '.';
COMMA      : ',';
SEMI       : ';';
COLON      : ':';
LPAREN     : '(';
RPAREN     : ')';
LBRACK     : '[';
RBRACK     : ']';
HASH       : '#';

// Anything else: reported by parse.cpp as an unexpected character.
ERROR_CHAR : . -> channel(ERRORS);

fragment A : [aA]; fragment B : [bB]; fragment C : [cC]; fragment D : [dD];
fragment E : [eE]; fragment F : [fF]; fragment G : [gG]; fragment H : [hH];
fragment I : [iI]; fragment J : [jJ]; fragment K : [kK]; fragment L : [lL];
fragment M : [mM]; fragment N : [nN]; fragment O : [oO]; fragment P : [pP];
fragment Q : [qQ]; fragment R : [rR]; fragment S : [sS]; fragment T : [tT];
fragment U : [uU]; fragment V : [vV]; fragment W : [wW]; fragment X : [xX];
fragment Y : [yY]; fragment Z : [zZ];
