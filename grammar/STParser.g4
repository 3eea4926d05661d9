// IEC 61131-3 (3rd edition) Structured Text parser, plus the common CODESYS
// extensions (methods, properties, interfaces, namespaces, AND_THEN/OR_ELSE,
// S=/R=/?=/REF=, pointers, references). The tree is converted into the AST of
// interpreter/ast/ast.h by interpreter/ast/ast_builder.cpp; the grammar is kept
// permissive where the builder can give a clearer message than the parser.
parser grammar STParser;

options { tokenVocab = STLexer; }

@parser::members {
  // Inside CASE: does a ':' come before anything that ends or starts a
  // statement? Then the tokens up to it are the labels of the next branch
  // (`3:`, `1, 2:`, `5..9:`, `Color.Red:`), and a `name:` there is such a
  // label, not a jump label inside the current branch. A statement has no
  // ':' of its own before its ';' except as a jump label.
  bool isCaseLabelAhead() {
    for (ssize_t i = 1; i < 100000; ++i) {
      switch (_input->LA(i)) {
        case COLON: return true;
        case SEMI: case ASSIGN: case TRY_ASSIGN: case ARROW: case antlr4::Token::EOF:
        case THEN: case DO: case OF: case ELSE: case ELSIF: case UNTIL:
        case IF: case CASE: case FOR: case WHILE: case REPEAT: case EXIT: case CONTINUE: case RETURN: case JMP:
        case END_IF: case END_CASE: case END_FOR: case END_WHILE: case END_REPEAT:
        case END_PROGRAM: case END_FUNCTION: case END_FUNCTION_BLOCK: case END_METHOD: case END_ACTION:
        case END_GET: case END_SET: case METHOD: case PROPERTY:
          return false;
        default: break;
      }
    }
    return false;
  }
  static bool isNameToken(size_t type) {
    return type == IDENTIFIER || type == GET || type == SET || type == TASK || type == ON ||
           type == WITH || type == READ_ONLY || type == READ_WRITE || type == ACTION;
  }
}

// ================================================================= files

compilationUnit
    : topLevelItem* EOF
    ;

topLevelItem
    : pouDecl
    | methodDecl
    | actionDecl              // CODESYS: an ACTION after the POU it belongs to
    | typeDecl
    | varBlock                // a top-level VAR_GLOBAL list (GVL)
    | configuration
    | namespaceDecl
    | usingDirective
    ;

namespaceDecl
    : NAMESPACE qualifiedName topLevelItem* END_NAMESPACE
    ;

usingDirective
    : USING qualifiedName (COMMA qualifiedName)* SEMI
    ;

// ================================================================= POUs

pouDecl
    : PROGRAM identifier pouElement* stmtList memberDecl* END_PROGRAM                     # programDecl
    | FUNCTION identifier (COLON returnType)? varBlock* stmtList END_FUNCTION             # functionDecl
    | FUNCTION_BLOCK modifier* identifier
        (EXTENDS qualifiedName)? (IMPLEMENTS qualifiedName (COMMA qualifiedName)*)?
        pouElement* stmtList memberDecl* END_FUNCTION_BLOCK                               # functionBlockDecl
    | INTERFACE identifier (EXTENDS qualifiedName (COMMA qualifiedName)*)?
        memberDecl* END_INTERFACE                                                         # interfaceDecl
    ;

pouElement
    : varBlock
    | memberDecl
    ;

memberDecl
    : methodDecl
    | propertyDecl
    | actionDecl
    ;

modifier
    : PUBLIC | PRIVATE | PROTECTED | INTERNAL | ABSTRACT | FINAL
    ;

methodDecl
    : METHOD modifier* identifier (COLON returnType)? varBlock* stmtList END_METHOD
    ;

// CODESYS/TwinCAT action: code of a PROGRAM or FUNCTION_BLOCK working on its
// variables, called as inst.Name() (or Name() inside the POU).
actionDecl
    : ACTION identifier COLON? stmtList END_ACTION SEMI?
    ;

propertyDecl
    : PROPERTY modifier* identifier COLON typeSpec propertyAccessor* END_PROPERTY
    ;

propertyAccessor
    : GET varBlock* stmtList END_GET      # propertyGetter
    | SET varBlock* stmtList END_SET      # propertySetter
    ;

// ================================================================= types

typeDecl
    : TYPE typeEntry* END_TYPE
    ;

typeEntry
    : identifier (EXTENDS qualifiedName)? COLON typeSpec (ASSIGN initializer)? SEMI?
    ;

typeSpec
    : ARRAY LBRACK arrayRange (COMMA arrayRange)* RBRACK OF typeSpec        # arrayType
    | (POINTER TO | REF_TO) typeSpec                                         # pointerType
    | REFERENCE TO typeSpec                                                  # referenceType
    | (STRING | WSTRING) (LBRACK expression RBRACK | LPAREN expression RPAREN)?   # stringType
    | STRUCT varDecl* END_STRUCT                                             # structType
    | UNION varDecl* END_UNION                                               # unionType   // CODESYS: members share storage
    | LPAREN enumValue (COMMA enumValue)* RPAREN qualifiedName?              # enumType
    | qualifiedName typeArguments?                                           # namedType
    ;

// After a type name: `INT (0..100)` (subrange), `INT (Red, Green)` (enumeration
// with a base type), `FB(1, x)` / `R_TRIG()` (CODESYS FB_init arguments).
typeArguments
    : LPAREN expression DOTDOT expression RPAREN                             # subrangeArgs
    | LPAREN enumValue (COMMA enumValue)* RPAREN                             # enumArgs
    | LPAREN argList? RPAREN                                                 # instanceArgs
    ;

// The result type of a FUNCTION or METHOD: the forms of typeSpec that fit
// there, without the ones with arguments in parentheses. A body may start
// with '(' after it; with typeSpec here, the choice after every type name
// (are arguments next?) needed more than one token of lookahead.
returnType
    : ARRAY LBRACK arrayRange (COMMA arrayRange)* RBRACK OF returnType      # arrayReturnType
    | (POINTER TO | REF_TO) returnType                                       # pointerReturnType
    | REFERENCE TO returnType                                                # referenceReturnType
    | (STRING | WSTRING) (LBRACK expression RBRACK | LPAREN expression RPAREN)?   # stringReturnType
    | qualifiedName                                                          # namedReturnType
    ;

arrayRange
    : expression DOTDOT expression
    | STAR
    ;

enumValue
    : identifier (ASSIGN expression)?
    ;

initializer
    : LBRACK arrayInitItem (COMMA arrayInitItem)* RBRACK                     # arrayInit
    | LPAREN structInitItem (COMMA structInitItem)* RPAREN                   # structInit
    | expression                                                             # exprInit
    ;

arrayInitItem
    : INTEGER LPAREN initializer? RPAREN
    | initializer
    ;

structInitItem
    : identifier ASSIGN initializer
    ;

// ================================================================= variables

// VAR_ACCESS has declarations of its own (`name : prog.var : INT READ_ONLY;`):
// with its path and access mode in every declaration, the choice after each
// name and after each type needed more than one token of lookahead.
varBlock
    : varSection varQualifier* varDecl* END_VAR
    | access=VAR_ACCESS varQualifier* accessDecl* END_VAR
    ;

varSection
    : VAR | VAR_INPUT | VAR_OUTPUT | VAR_IN_OUT | VAR_TEMP | VAR_STAT | VAR_INST
    | VAR_GLOBAL | VAR_EXTERNAL | VAR_CONFIG
    ;

varQualifier
    : CONSTANT | RETAIN | NON_RETAIN | PERSISTENT
    ;

// `a, b AT %IX0.0 : INT := 5;` — also the looser form of VAR_CONFIG
// (`prog.x AT %QW1 : INT;`). Tokens the AST builder asks about have labels
// (semi=, address=, init=, and colon=, assign=, eq=, setOperator= in
// exprStmt; operands+= and suffixes+= in expressions): a label is a field,
// the generated accessor a search of the children.
varDecl
    : varName (COMMA varName)* (AT address=DIRECT_ADDRESS)? COLON
        typeSpec (ASSIGN init=initializer)? semi=SEMI?   // a missing ';' is reported by the AST builder
    ;

accessDecl
    : varName COLON accessPath COLON typeSpec (READ_ONLY | READ_WRITE)? SEMI
    ;

varName
    : identifier (DOT member=(IDENTIFIER | GET | SET | TASK | ON | WITH | READ_ONLY | READ_WRITE | ACTION
                             | INTEGER | PARTIAL_ACCESS) | LBRACK expressionList RBRACK)*
    ;

accessPath
    : identifier (DOT member=(IDENTIFIER | GET | SET | TASK | ON | WITH | READ_ONLY | READ_WRITE | ACTION
                             | INTEGER | PARTIAL_ACCESS) | LBRACK expressionList RBRACK)*
    ;

// ================================================================= configuration

configuration
    : CONFIGURATION identifier configElement* END_CONFIGURATION
    ;

configElement
    : varBlock
    | resource
    | taskDecl
    | programConfig
    ;

resource
    : RESOURCE identifier (ON qualifiedName)? resourceElement* END_RESOURCE
    ;

resourceElement
    : varBlock
    | taskDecl
    | programConfig
    ;

taskDecl
    : TASK anyName LPAREN (taskParam (COMMA taskParam)*)? RPAREN SEMI
    ;

taskParam
    : anyName ASSIGN expression
    ;

programConfig
    : PROGRAM (RETAIN | NON_RETAIN)? identifier (WITH anyName)? COLON qualifiedName
        (LPAREN argList? RPAREN)? SEMI                                           # programInstance
    | identifier WITH anyName SEMI                                              # fbTaskBinding
    ;

// ================================================================= statements

stmtList
    : statement*
    ;

// `name:` (a jump label) is an expression statement ending in ':' for the
// parser and a label for the AST builder, which checks that it is a name:
// as two alternatives starting with the same name, the choice between them
// needed adaptive prediction on every statement. The ';' after END_IF and
// the like is an empty statement for the same reason (the builder drops it).
statement
    : expression (((assign=(ASSIGN | TRY_ASSIGN) expression | setOperator=identifier eq=EQ expression)? SEMI) | colon=COLON)   # exprStmt
    | IF expression THEN stmtList (ELSIF expression THEN stmtList)* (ELSE stmtList)? END_IF  # ifStmt
    | CASE expression OF caseBranch* (ELSE stmtList)? END_CASE                   # caseStmt
    | FOR identifier ASSIGN expression TO expression (BY expression)? DO stmtList END_FOR  # forStmt
    | WHILE expression DO stmtList END_WHILE                                     # whileStmt
    | REPEAT stmtList UNTIL expression END_REPEAT                                # repeatStmt
    | EXIT SEMI                                                                  # exitStmt
    | CONTINUE SEMI                                                              # continueStmt
    | RETURN SEMI                                                                # returnStmt
    | JMP identifier SEMI                                                        # jmpStmt
    | SEMI                                                                       # emptyStmt
    ;

// Inside CASE, `IDENT :` starts a new case label, so a branch body cannot
// contain a jump label at its top level.
caseBranch
    : caseLabel (COMMA caseLabel)* COLON caseBody
    ;

caseBody
    : caseStatement*
    ;

caseStatement
    : {!isCaseLabelAhead()}? statement
    ;

caseLabel
    : expression (DOTDOT expression)?
    ;

// ================================================================= expressions

// An operand chain; the AST builder applies the IEC precedence, highest
// first: postfix (call, member, index, ^), unary, **, * / MOD, + -,
// comparisons, = <>, AND & AND_THEN, XOR, OR OR_ELSE; all left-associative.
// As a flat list rather than one left-recursive rule with a precedence
// predicate per level, every decision here and in the rules around it is
// LL(1): the parser predicts from one token instead of running ANTLR's
// adaptive prediction (decision 0158).
expression
    : operands+=unaryExpr (ops+=(POW | STAR | SLASH | MOD | PLUS | MINUS | LT_OP | GT_OP | LE | GE | EQ | NE
                     | AND | AMP | AND_THEN | XOR | OR | OR_ELSE) operands+=unaryExpr)*
    ;

// An operand. Names, the primaries and the literals are tokens of this rule
// rather than rules of their own (`identifier`, `literal`): every rule a
// parse enters costs a context object, two dynamic casts and a destructor,
// and operands are most of a program (decision 0158). The name tokens are
// those of `identifier`.
unaryExpr
    : op=(MINUS | PLUS | NOT) unaryExpr                                   # unaryExpression
    | value=(INTEGER | BASED_INTEGER | REAL_LITERAL | TRUE | FALSE | STRING_LITERAL | WSTRING_LITERAL
            | DURATION_LITERAL | DATE_LITERAL | TOD_LITERAL | DT_LITERAL | TYPED_LITERAL)   # literalExpression
    | ( name=(IDENTIFIER | GET | SET | TASK | ON | WITH | READ_ONLY | READ_WRITE | ACTION)
      | keywordFunction=(MOD | AND | OR | XOR)   // MOD(a, b), AND(a, b, c): the standard functions named like operators
      | THIS
      | SUPER
      | DIRECT_ADDRESS
      | LPAREN expression RPAREN
      ) suffixes+=postfixOp*                                              # postfixExpression
    ;

postfixOp
    : DOT member=(IDENTIFIER | GET | SET | TASK | ON | WITH | READ_ONLY | READ_WRITE | ACTION
                 | INTEGER | PARTIAL_ACCESS)   # memberOp   // a name (the tokens of `identifier`), a bit number, %X3
    | LBRACK expressionList RBRACK        # indexOp
    | CARET                               # derefOp
    | LPAREN argList? RPAREN              # callOp
    ;

expressionList
    : expression (COMMA expression)*
    ;

argList
    : arg (COMMA arg)*
    ;

// `name := value`, `name => variable` (`NOT name => variable`), `value`:
// one shape for the parser, told apart by the AST builder, so that the
// choice needs one token of lookahead.
arg
    : expression (op=(ASSIGN | ARROW) expression?)?
    ;

// ================================================================= names

// A dotted name: its parts are tokens (those of `identifier`), not rules,
// as every type name of a declaration is one (decision 0158).
qualifiedName
    : (IDENTIFIER | GET | SET | TASK | ON | WITH | READ_ONLY | READ_WRITE | ACTION)
      (DOT (IDENTIFIER | GET | SET | TASK | ON | WITH | READ_ONLY | READ_WRITE | ACTION))*
    ;

// Soft keywords: words with a meaning in one place that stay usable as names.
identifier
    : IDENTIFIER | GET | SET | TASK | ON | WITH | READ_ONLY | READ_WRITE | ACTION
    ;

// Task names and task parameter names: any word, keywords included
// (`TASK While (...)`, `REPEAT := DAILY`, `AT := DT#...`).
anyName
    : identifier | WHILE | REPEAT | FOR | IF | CASE | EXIT | CONTINUE | RETURN | AT
    | TYPE | STRING | WSTRING | END_IF | UNTIL | THEN | ELSE | DO | BY | TO | OF
    | CONSTANT | RETAIN | NON_RETAIN | PERSISTENT | METHOD | PROPERTY | INTERFACE
    | INTERNAL | PUBLIC | PRIVATE | PROTECTED | FINAL | ABSTRACT | POINTER | REFERENCE
    | ARRAY | STRUCT | FUNCTION | USING | NAMESPACE | JMP | AND | OR | XOR | NOT | MOD
    ;
