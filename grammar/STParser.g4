// IEC 61131-3 (3rd edition) Structured Text parser, plus the common CODESYS
// extensions (methods, properties, interfaces, namespaces, AND_THEN/OR_ELSE,
// S=/R=/?=/REF=, pointers, references). The tree is converted into the AST of
// interpreter/ast/ast.h by interpreter/ast/ast_builder.cpp; the grammar is kept
// permissive where the builder can give a clearer message than the parser.
parser grammar STParser;

options { tokenVocab = STLexer; }

@parser::members {
  // Inside CASE: is the next thing `name{.name} :` (not `:=`)? Then it is the
  // label of the next branch, not a jump label inside the current one.
  bool isCaseLabelAhead() {
    size_t i = 1;
    if (!isNameToken(_input->LA(i))) return false;
    ++i;
    while (_input->LA(i) == DOT && isNameToken(_input->LA(i + 1))) i += 2;
    return _input->LA(i) == COLON;
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
    | FUNCTION identifier (COLON typeSpec)? varBlock* stmtList END_FUNCTION               # functionDecl
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
    : METHOD modifier* identifier (COLON typeSpec)? varBlock* stmtList END_METHOD
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
    | qualifiedName LPAREN expression DOTDOT expression RPAREN               # subrangeType
    | qualifiedName LPAREN enumValue (COMMA enumValue)* RPAREN               # typedEnumType
    | qualifiedName LPAREN argList? RPAREN                                   # instanceArgsType   // CODESYS `fb : FB(1, x)`, `t : R_TRIG()`: FB_init arguments
    | qualifiedName                                                          # namedType
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

varBlock
    : varSection varQualifier* varDecl* END_VAR
    ;

varSection
    : VAR | VAR_INPUT | VAR_OUTPUT | VAR_IN_OUT | VAR_TEMP | VAR_STAT | VAR_INST
    | VAR_GLOBAL | VAR_EXTERNAL | VAR_ACCESS | VAR_CONFIG
    ;

varQualifier
    : CONSTANT | RETAIN | NON_RETAIN | PERSISTENT
    ;

// `a, b AT %IX0.0 : INT := 5;` — also the looser forms of VAR_CONFIG
// (`prog.x AT %QW1 : INT;`) and VAR_ACCESS (`name : prog.var : INT READ_ONLY;`).
varDecl
    : varName (COMMA varName)* (AT DIRECT_ADDRESS)? COLON (accessPath COLON)?
        typeSpec (ASSIGN initializer)? (READ_ONLY | READ_WRITE)? SEMI?   // a missing ';' is reported by the AST builder
    ;

varName
    : identifier (DOT memberName | LBRACK expressionList RBRACK)*
    ;

accessPath
    : identifier (DOT memberName | LBRACK expressionList RBRACK)*
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

statement
    : identifier COLON                                                          # labelStmt
    | expression ((ASSIGN | TRY_ASSIGN) expression | identifier EQ expression)? SEMI   # exprStmt
    | IF expression THEN stmtList (ELSIF expression THEN stmtList)* (ELSE stmtList)? END_IF SEMI?  # ifStmt
    | CASE expression OF caseBranch* (ELSE stmtList)? END_CASE SEMI?             # caseStmt
    | FOR identifier ASSIGN expression TO expression (BY expression)? DO stmtList END_FOR SEMI?  # forStmt
    | WHILE expression DO stmtList END_WHILE SEMI?                               # whileStmt
    | REPEAT stmtList UNTIL expression END_REPEAT SEMI?                          # repeatStmt
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

// IEC precedence, highest first: postfix (call, member, index, ^), unary,
// **, * / MOD, + -, comparisons, = <>, AND & AND_THEN, XOR, OR OR_ELSE.
expression
    : postfixExpr                                            # postfixExpression
    | literal                                                # literalExpression
    | op=(MINUS | PLUS | NOT) expression                     # unaryExpression
    | expression op=POW expression                           # binaryExpression
    | expression op=(STAR | SLASH | MOD) expression          # binaryExpression
    | expression op=(PLUS | MINUS) expression                # binaryExpression
    | expression op=(LT_OP | GT_OP | LE | GE) expression     # binaryExpression
    | expression op=(EQ | NE) expression                     # binaryExpression
    | expression op=(AND | AMP | AND_THEN) expression        # binaryExpression
    | expression op=XOR expression                           # binaryExpression
    | expression op=(OR | OR_ELSE) expression                # binaryExpression
    ;

// Postfix operators are an iteration, not a recursion: a long chain
// `a.b.c[1]^.d()` costs no parser stack.
postfixExpr
    : primary postfixOp*
    ;

primary
    : identifier
    | keywordFunction=(MOD | AND | OR | XOR)   // MOD(a, b), AND(a, b, c): the standard functions named like operators
    | THIS
    | SUPER
    | DIRECT_ADDRESS
    | LPAREN expression RPAREN
    ;

postfixOp
    : DOT memberName                      # memberOp
    | LBRACK expressionList RBRACK        # indexOp
    | CARET                               # derefOp
    | LPAREN argList? RPAREN              # callOp
    ;

memberName
    : identifier
    | INTEGER
    | PARTIAL_ACCESS
    ;

expressionList
    : expression (COMMA expression)*
    ;

argList
    : arg (COMMA arg)*
    ;

arg
    : identifier ASSIGN expression?          # inputArg
    | NOT? identifier ARROW expression?      # outputArg
    | expression                             # positionalArg
    ;

literal
    : INTEGER
    | BASED_INTEGER
    | REAL_LITERAL
    | TRUE
    | FALSE
    | STRING_LITERAL
    | WSTRING_LITERAL
    | DURATION_LITERAL
    | DATE_LITERAL
    | TOD_LITERAL
    | DT_LITERAL
    | TYPED_LITERAL
    ;

// ================================================================= names

qualifiedName
    : identifier (DOT identifier)*
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
