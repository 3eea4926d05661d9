// IEC 61131-3 (3rd edition) Structured Text lexer, plus the common CODESYS
// extensions. Keywords are case-insensitive (fragment letter rules, because the
// ANTLR tool in use predates the caseInsensitive option).
//
// Channels: comments and whitespace are skipped (nothing reads them, and a
// large file has millions); `{...}` pragmas go to PRAGMAS so the
// AST builder can attach them to the declaration they precede; malformed input
// (unterminated comments/strings/pragmas, stray characters) becomes tokens on
// the ERRORS channel, which parse.cpp reports with their exact location, so the
// lexer itself never fails.
lexer grammar STLexer;

channels { PRAGMAS, ERRORS }

// Produced by the BLOCK_COMMENT action, never matched by a rule of its own.
tokens { UNTERMINATED_BLOCK_COMMENT }

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
PRAGMA        : '{' ~[}]* '}' -> channel(PRAGMAS);
UNTERMINATED_PRAGMA : '{' ~[}]* EOF -> channel(ERRORS);

// ------------------------------------------------------------------ literals
// Time and date literals come before TYPED_LITERAL: for the same prefix the
// longer (complete) match wins, and on a tie the earlier rule.
DURATION_LITERAL
    : (T | T I M E | L T | L T I M E) '#' ('+' | '-')? DURATION_PART+
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

// %IX0.0, %QW2, %MD10, %I*, %Q*
DIRECT_ADDRESS : '%' (I | Q | M) (X | B | W | D | L)? ( [0-9]+ ('.' [0-9]+)* | '*' );
// x.%X3 (partial access of a bit string)
PARTIAL_ACCESS : '%' (X | B | W | D | L) [0-9]+;

fragment DEC_INT   : [0-9] ('_'? [0-9])*;
fragment BASED_INT : ('2' | '8' | '10' | '16') '#' '_'? [0-9a-fA-F] ('_'? [0-9a-fA-F])*;
fragment REAL_FRAG : DEC_INT '.' DEC_INT EXPONENT? | DEC_INT EXPONENT;
fragment EXPONENT  : E ('+' | '-')? DEC_INT;
fragment SQ_STRING : '\'' ( ~['$\r\n] | '$' ~[\r\n] )* '\'';
fragment DQ_STRING : '"' ( ~["$\r\n] | '$' ~[\r\n] )* '"';
fragment DURATION_PART : [0-9] [0-9_]* ('.' [0-9]+)? (D | H | M | S | M S | U S | N S) '_'?;
fragment DATE_VALUE : [0-9]+ '-' [0-9]+ '-' [0-9]+;
fragment TOD_VALUE  : [0-9]+ ':' [0-9]+ (':' [0-9]+ ('.' [0-9]+)?)?;

// ------------------------------------------------------------------ keywords
PROGRAM            : P R O G R A M;
END_PROGRAM        : E N D '_' P R O G R A M;
FUNCTION           : F U N C T I O N;
END_FUNCTION       : E N D '_' F U N C T I O N;
FUNCTION_BLOCK     : F U N C T I O N '_' B L O C K;
END_FUNCTION_BLOCK : E N D '_' F U N C T I O N '_' B L O C K;
METHOD             : M E T H O D;
END_METHOD         : E N D '_' M E T H O D;
ACTION             : A C T I O N;
END_ACTION         : E N D '_' A C T I O N;
PROPERTY           : P R O P E R T Y;
END_PROPERTY       : E N D '_' P R O P E R T Y;
INTERFACE          : I N T E R F A C E;
END_INTERFACE      : E N D '_' I N T E R F A C E;
NAMESPACE          : N A M E S P A C E;
END_NAMESPACE      : E N D '_' N A M E S P A C E;
USING              : U S I N G;
TYPE               : T Y P E;
END_TYPE           : E N D '_' T Y P E;
STRUCT             : S T R U C T;
END_STRUCT         : E N D '_' S T R U C T;
UNION              : U N I O N;
END_UNION          : E N D '_' U N I O N;
ARRAY              : A R R A Y;
OF                 : O F;
STRING             : S T R I N G;
WSTRING            : W S T R I N G;
POINTER            : P O I N T E R;
REF_TO             : R E F '_' T O;   // IEC 61131-3 3rd edition references: a typed pointer
REFERENCE          : R E F E R E N C E;
TO                 : T O;
EXTENDS            : E X T E N D S;
IMPLEMENTS         : I M P L E M E N T S;
ABSTRACT           : A B S T R A C T;
FINAL              : F I N A L;
PUBLIC             : P U B L I C;
PRIVATE            : P R I V A T E;
PROTECTED          : P R O T E C T E D;
INTERNAL           : I N T E R N A L;
THIS               : T H I S;
SUPER              : S U P E R;
END_GET            : E N D '_' G E T;
END_SET            : E N D '_' S E T;
// GET and SET are soft keywords (SET is an input of the standard RS block).
GET                : G E T;
SET                : S E T;

VAR                : V A R;
VAR_INPUT          : V A R '_' I N P U T;
VAR_OUTPUT         : V A R '_' O U T P U T;
VAR_IN_OUT         : V A R '_' I N '_' O U T;
VAR_TEMP           : V A R '_' T E M P;
VAR_STAT           : V A R '_' S T A T;
VAR_INST           : V A R '_' I N S T;
VAR_GLOBAL         : V A R '_' G L O B A L;
VAR_EXTERNAL       : V A R '_' E X T E R N A L;
VAR_ACCESS         : V A R '_' A C C E S S;
VAR_CONFIG         : V A R '_' C O N F I G;
END_VAR            : E N D '_' V A R;
CONSTANT           : C O N S T A N T;
RETAIN             : R E T A I N;
NON_RETAIN         : N O N '_' R E T A I N;
PERSISTENT         : P E R S I S T E N T;
AT                 : A T;

CONFIGURATION      : C O N F I G U R A T I O N;
END_CONFIGURATION  : E N D '_' C O N F I G U R A T I O N;
RESOURCE           : R E S O U R C E;
END_RESOURCE       : E N D '_' R E S O U R C E;
// TASK, ON, WITH, READ_ONLY, READ_WRITE are soft keywords (usable as names).
TASK               : T A S K;
ON                 : O N;
WITH               : W I T H;
READ_ONLY          : R E A D '_' O N L Y;
READ_WRITE         : R E A D '_' W R I T E;

IF                 : I F;
THEN               : T H E N;
ELSIF              : E L S I F;
ELSE               : E L S E;
END_IF             : E N D '_' I F;
CASE               : C A S E;
END_CASE           : E N D '_' C A S E;
FOR                : F O R;
BY                 : B Y;
DO                 : D O;
END_FOR            : E N D '_' F O R;
WHILE              : W H I L E;
END_WHILE          : E N D '_' W H I L E;
REPEAT             : R E P E A T;
UNTIL              : U N T I L;
END_REPEAT         : E N D '_' R E P E A T;
EXIT               : E X I T;
CONTINUE           : C O N T I N U E;
RETURN             : R E T U R N;
JMP                : J M P;

AND_THEN           : A N D '_' T H E N;
OR_ELSE            : O R '_' E L S E;
AND                : A N D;
OR                 : O R;
XOR                : X O R;
NOT                : N O T;
MOD                : M O D;
TRUE               : T R U E;
FALSE              : F A L S E;

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
