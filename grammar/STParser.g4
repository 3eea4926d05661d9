// IEC 61131-3 (3rd edition) Structured Text parser, plus the common CODESYS
// extensions (methods, properties, interfaces, namespaces, AND_THEN/OR_ELSE,
// S=/R=/?=/REF=, pointers, references). The tree is converted into the AST of
// interpreter/ast/ast.h by interpreter/ast/ast_builder.cpp; the grammar is kept
// permissive where the builder can give a clearer message than the parser.
//
// Every rule reference and token the AST builder reads has a label (name=,
// items+=, ...): the parser builds no parse tree (decision 0159), so the
// labels, the start and stop tokens of each context are all there is. The
// generated accessors (identifier(), END_IF(), ...) search a context's
// children and find nothing.
parser grammar STParser;

options { tokenVocab = STLexer; contextSuperClass = ArenaRuleContext; }

@parser::header {
#include "grammar/arena_rule_context.h"
}

@parser::members {
  // Parser::exitRule of ANTLR 4.9, without its dynamic_cast of the parent
  // (a generated parser's contexts are all ParserRuleContexts): a rule's
  // generated code calls exitRule() unqualified, so this one hides the
  // base's. The dynamic_cast compared type names with strcmp on every rule
  // exit: 3 % of `strun check` (decision 0159).
  void exitRule() {
    _ctx->stop = _matchedEOF ? _input->LT(1) : _input->LT(-1);
    if (!_parseListeners.empty()) triggerExitRuleEvent();
    setState(_ctx->invokingState);
    _ctx = static_cast<antlr4::ParserRuleContext*>(_ctx->parent);
  }
  // The generated `auto onExit = finally([=] { exitRule(); });` of every
  // rule finds this before antlrcpp::finally, which wraps the lambda in a
  // std::function (an allocation-free but indirect call, 2 % of a check).
  template <typename Action>
  struct OnExit {
    Action action;
    ~OnExit() { action(); }
  };
  template <typename Action>
  static OnExit<Action> finally(Action action) { return OnExit<Action>{std::move(action)}; }

  static bool isNameToken(size_t type) {
    return type == IDENTIFIER || type == GET || type == SET || type == TASK || type == ON ||
           type == WITH || type == READ_ONLY || type == READ_WRITE;
  }
}

// ================================================================= files

compilationUnit
    : items+=topLevelItem* EOF
    ;

topLevelItem
    : pou=pouDecl
    | method=methodDecl
    | action=actionDecl       // CODESYS: an ACTION after the POU it belongs to
    | types=typeDecl
    | globals=varBlock        // a top-level VAR_GLOBAL list (GVL)
    | config=configuration
    | space=namespaceDecl
    | uses=usingDirective
    ;

namespaceDecl
    : NAMESPACE name=qualifiedName items+=topLevelItem* END_NAMESPACE
    ;

usingDirective
    : USING names+=qualifiedName (COMMA names+=qualifiedName)* SEMI
    ;

// ================================================================= POUs

pouDecl
    : PROGRAM modifiers+=modifier* name=identifier headerEnd=SEMI? elements+=pouElement* (body=pouBody members+=memberDecl*)? end=END_PROGRAM   # programDecl
    | FUNCTION modifiers+=modifier* name=identifier (COLON result=returnType)? headerEnd=SEMI? vars+=varBlock* body=stmtList end=END_FUNCTION # functionDecl
    | FUNCTION_BLOCK modifiers+=modifier* name=identifier
        (EXTENDS base=qualifiedName baseGeneric=genericArguments?)? (IMPLEMENTS interfaces+=qualifiedName (COMMA interfaces+=qualifiedName)* COMMA?)?
        headerEnd=SEMI? elements+=pouElement* (body=pouBody members+=memberDecl*)? end=END_FUNCTION_BLOCK              # functionBlockDecl
    | INTERFACE modifiers+=modifier* name=identifier (EXTENDS bases+=qualifiedName (COMMA bases+=qualifiedName)* COMMA?)?
        headerEnd=SEMI? members+=memberDecl* end=END_INTERFACE                                                         # interfaceDecl
    // IEC 61131-3 Ed.3 / SIMATIC AX: a CLASS is a function block without a body.
    | CLASS modifiers+=modifier* name=identifier
        (EXTENDS base=qualifiedName baseGeneric=genericArguments?)? (IMPLEMENTS interfaces+=qualifiedName (COMMA interfaces+=qualifiedName)* COMMA?)?
        headerEnd=SEMI? elements+=pouElement* end=END_CLASS                                            # classDecl
    ;

pouElement
    : vars=varBlock
    | member=memberDecl
    ;

// The statements of a PROGRAM or FUNCTION_BLOCK, with methods, properties
// and actions before or after them. Not empty: with an empty body allowed
// between the members before and after it, which of the two lists a METHOD
// belongs to needed adaptive prediction after every member.
pouBody
    : statements+=statement+
    ;

memberDecl
    : method=methodDecl
    | property=propertyDecl
    | action=actionDecl
    ;

modifier
    : PUBLIC | PRIVATE | PROTECTED | INTERNAL | ABSTRACT | FINAL
    | OVERRIDE   // Ed.3 / SIMATIC AX; the scanner step marks it (decision 0210)
    ;

methodDecl
    : METHOD modifiers+=modifier* name=identifier (COLON result=returnType)? headerEnd=SEMI? vars+=varBlock* body=stmtList end=END_METHOD
    ;

// CODESYS/TwinCAT action: code of a PROGRAM or FUNCTION_BLOCK working on its
// variables, called as inst.Name() (or Name() inside the POU).
actionDecl
    : ACTION name=identifier COLON? body=stmtList end=END_ACTION SEMI?
    ;

propertyDecl
    : PROPERTY modifiers+=modifier* name=identifier COLON type=typeSpec headerEnd=SEMI? accessors+=propertyAccessor* END_PROPERTY
    ;

propertyAccessor
    : GET modifiers+=modifier* vars+=varBlock* body=stmtList end=END_GET      # propertyGetter   // TwinCAT: `SET PROTECTED`
    | SET modifiers+=modifier* vars+=varBlock* body=stmtList end=END_SET      # propertySetter
    ;

// ================================================================= types

typeDecl
    : TYPE modifiers+=modifier* entries+=typeEntry* END_TYPE
    ;

typeEntry
    : name=identifier (EXTENDS base=qualifiedName)? COLON type=typeSpec (ASSIGN init=initializer)? SEMI?
    ;

typeSpec
    : ARRAY LBRACK ranges+=arrayRange (COMMA ranges+=arrayRange)* RBRACK OF element=typeSpec   # arrayType
    | (POINTER TO | REF_TO) element=typeSpec                                 # pointerType
    | REFERENCE TO element=typeSpec (refOperator=identifier EQ refInit=expression)?   # referenceType   // TwinCAT `r : REFERENCE TO INT REF= x;`
    | kind=(STRING | WSTRING) (LBRACK length=expression RBRACK | LPAREN length=expression RPAREN)?   # stringType
    | STRUCT fields+=varDecl* END_STRUCT                                     # structType
    | UNION fields+=varDecl* END_UNION                                       # unionType   // CODESYS: members share storage
    | LPAREN values+=enumValue (COMMA values+=enumValue)* RPAREN base=qualifiedName?   # enumType
    | name=qualifiedName generic=genericArguments? arguments=typeArguments?  # namedType
    ;

// The values of a block's VAR_GENERIC CONSTANTs (TwinCAT 4026 / CODESYS):
// `FB_X<6>`, `FB_X<(2 * cMax)>`, `FB_X<cMax, 3>`.
genericArguments
    : LT_OP values+=genericArgument (COMMA values+=genericArgument)* GT_OP
    ;

genericArgument
    : LPAREN value=expression RPAREN
    | sign=MINUS? number=(INTEGER | BASED_INTEGER | TYPED_LITERAL)
    | name=qualifiedName
    ;

// After a type name: `INT (0..100)` (subrange), `INT (Red, Green)` (enumeration
// with a base type), `FB(1, x)` / `R_TRIG()` (CODESYS FB_init arguments),
// `FB[(1), (2)]` (one argument list per element of an ARRAY OF FB).
typeArguments
    : LPAREN lo=expression DOTDOT hi=expression RPAREN                       # subrangeArgs
    | LPAREN values+=enumValue (COMMA values+=enumValue)* RPAREN             # enumArgs
    | LPAREN args=argList? RPAREN                                            # instanceArgs
    | LBRACK elements+=elementArgs (COMMA elements+=elementArgs)* RBRACK     # perElementArgs   // `ARRAY[1..2] OF FB_X[(a := 1), (a := 2)]`
    ;

// The FB_init arguments of one element of an array of blocks (decision 0330).
elementArgs
    : LPAREN args=argList? RPAREN
    ;

// The result type of a FUNCTION or METHOD: the forms of typeSpec that fit
// there, without the ones with arguments in parentheses. A body may start
// with '(' after it; with typeSpec here, the choice after every type name
// (are arguments next?) needed more than one token of lookahead.
returnType
    : ARRAY LBRACK ranges+=arrayRange (COMMA ranges+=arrayRange)* RBRACK OF element=returnType   # arrayReturnType
    | (POINTER TO | REF_TO) element=returnType                               # pointerReturnType
    | REFERENCE TO element=returnType                                        # referenceReturnType
    | kind=(STRING | WSTRING) (LBRACK length=expression RBRACK | LPAREN length=expression RPAREN)?   # stringReturnType
    | name=qualifiedName (LPAREN lo=expression DOTDOT hi=expression RPAREN)?  # namedReturnType
    ;

arrayRange
    : lo=expression DOTDOT hi=expression
    | star=STAR
    ;

enumValue
    : name=identifier (ASSIGN value=expression)?
    ;

initializer
    : LBRACK items+=arrayInitItem (COMMA items+=arrayInitItem)* RBRACK       # arrayInit
    | LPAREN (fields+=structInitItem (COMMA fields+=structInitItem)*)? RPAREN   # structInit   // `fb : FB_X := ();` (TwinCAT)
    | value=expression                                                       # exprInit
    ;

arrayInitItem
    : count=INTEGER LPAREN value=initializer? RPAREN
    | value=initializer
    ;

structInitItem
    : name=identifier ASSIGN value=initializer
    ;

// ================================================================= variables

// VAR_ACCESS has declarations of its own (`name : prog.var : INT READ_ONLY;`):
// with its path and access mode in every declaration, the choice after each
// name and after each type needed more than one token of lookahead.
varBlock
    : section=varSection qualifiers+=varQualifier* decls+=varDecl* END_VAR
    | access=VAR_ACCESS qualifiers+=varQualifier* accessDecls+=accessDecl* END_VAR
    ;

varSection
    : VAR | VAR_INPUT | VAR_OUTPUT | VAR_IN_OUT | VAR_TEMP | VAR_STAT | VAR_INST | VAR_GENERIC
    | VAR_GLOBAL | VAR_EXTERNAL | VAR_CONFIG
    ;

varQualifier
    : CONSTANT | RETAIN | NON_RETAIN | PERSISTENT
    | PUBLIC | PRIVATE | PROTECTED | INTERNAL   // Ed.3 `VAR PUBLIC` in a CLASS (decision 0209)
    ;

// `a, b AT %IX0.0 : INT := 5;` — also the looser form of VAR_CONFIG
// (`prog.x AT %QW1 : INT;`), IEC's located declaration without a name
// (`AT %MW1 : INT := 2;`) and its edge-detecting inputs (`x : BOOL R_EDGE;`).
varDecl
    : (names+=varName (COMMA names+=varName)*)? (AT address=DIRECT_ADDRESS)? COLON
        type=typeSpec edge=(R_EDGE | F_EDGE)? (ASSIGN init=initializer)? semi=SEMI?   // a missing ';' is reported by the AST builder
    ;

accessDecl
    : name=varName COLON path=accessPath COLON type=typeSpec accessMode=(READ_ONLY | READ_WRITE)? SEMI
    ;

varName
    : identifier (DOT member=(IDENTIFIER | GET | SET | TASK | ON | WITH | READ_ONLY | READ_WRITE
                             | INTEGER | PARTIAL_ACCESS) | LBRACK expressionList RBRACK)*
    ;

accessPath
    : identifier (DOT member=(IDENTIFIER | GET | SET | TASK | ON | WITH | READ_ONLY | READ_WRITE
                             | INTEGER | PARTIAL_ACCESS) | LBRACK expressionList RBRACK)*
    ;

// ================================================================= configuration

configuration
    : CONFIGURATION name=identifier elements+=configElement* END_CONFIGURATION
    ;

configElement
    : vars=varBlock
    | res=resource
    | task=taskDecl
    | program=programConfig
    ;

resource
    : RESOURCE name=identifier (ON target=qualifiedName)? elements+=resourceElement* END_RESOURCE
    ;

resourceElement
    : vars=varBlock
    | task=taskDecl
    | program=programConfig
    ;

taskDecl
    : TASK name=anyName LPAREN (params+=taskParam (COMMA params+=taskParam)*)? RPAREN SEMI
    ;

taskParam
    : name=anyName ASSIGN value=expression
    ;

programConfig
    : PROGRAM (RETAIN | NON_RETAIN)? name=identifier (WITH task=anyName)? COLON type=qualifiedName
        (LPAREN args=argList? RPAREN)? SEMI                                      # programInstance
    | name=identifier WITH task=anyName SEMI                                    # fbTaskBinding
    ;

// ================================================================= statements

stmtList
    : statements+=statement*
    ;

// `name:` (a jump label) and the labels of a CASE branch (`3:`, `1, 2:`,
// `5..9:`, `Color.Red:`) are an expression statement ending in ':' for the
// parser; the AST builder makes a jump label of it (a name) or, directly
// in a CASE, the start of the next branch. As alternatives of their own,
// each starting with an expression like the statement after it, the
// choice needed adaptive prediction on every statement (and a look ahead
// to the ':' in CASE). The ';' after END_IF and the like is an empty
// statement for the same reason (the builder drops it).
statement
    : parts+=expression (((assign=(ASSIGN | TRY_ASSIGN) parts+=expression (ASSIGN parts+=expression)* | setOperator=identifier eq=EQ parts+=expression)? SEMI)
                         | (dots=DOTDOT hi=expression)? (COMMA moreLabels+=caseLabel)* colon=COLON)   # exprStmt
    | IF conds+=expression THEN blocks+=stmtList (ELSIF conds+=expression THEN blocks+=stmtList)*
        (ELSE elseBlock=stmtList)? END_IF                                        # ifStmt
    | CASE selector=expression OF body=stmtList (ELSE elseBlock=stmtList)? END_CASE   # caseStmt
    | FOR control=unaryExpr ASSIGN from=expression TO to=expression (by=BY step=expression)? DO body=stmtList END_FOR  # forStmt
    | WHILE cond=expression DO body=stmtList END_WHILE                           # whileStmt
    | REPEAT body=stmtList UNTIL cond=expression END_REPEAT                      # repeatStmt
    | EXIT SEMI                                                                  # exitStmt
    | CONTINUE SEMI                                                              # continueStmt
    | RETURN cond=expression? SEMI                                               # returnStmt   // `RETURN (done);` conditional (CODESYS)
    | JMP target=identifier SEMI                                                 # jmpStmt
    | SEMI                                                                       # emptyStmt
    ;

// A CASE label after the first of a list (`1, 5..9, 12:`).
caseLabel
    : lo=expression (dots=DOTDOT hi=expression)?
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
// parse enters costs a context object, its entry and exit and a destructor,
// and operands are most of a program (decision 0158). The name tokens are
// those of `identifier`.
unaryExpr
    : op=(MINUS | PLUS | NOT) operand=unaryExpr                           # unaryExpression
    | value=(INTEGER | BASED_INTEGER | REAL_LITERAL | TRUE | FALSE | STRING_LITERAL | WSTRING_LITERAL
            | DURATION_LITERAL | DATE_LITERAL | TOD_LITERAL | DT_LITERAL | TYPED_LITERAL)   # literalExpression
    | ( name=(IDENTIFIER | GET | SET | TASK | ON | WITH | READ_ONLY | READ_WRITE)
      | keywordFunction=(MOD | AND | OR | XOR)   // MOD(a, b), AND(a, b, c): the standard functions named like operators
      | special=(THIS | SUPER | DIRECT_ADDRESS)
      | LPAREN inner=expression (ASSIGN assigned=expression)? RPAREN
      ) suffixes+=postfixOp*                                              # postfixExpression
    | POINTER TO pointee=qualifiedName   # pointerTypeExpression   // __NEW(POINTER TO T, n) (TwinCAT)
    ;

postfixOp
    : DOT member=(IDENTIFIER | GET | SET | TASK | ON | WITH | READ_ONLY | READ_WRITE
                 | INTEGER | PARTIAL_ACCESS)   # memberOp   // a name (the tokens of `identifier`), a bit number, %X3
    | LBRACK indexes=expressionList RBRACK   # indexOp
    | CARET                                  # derefOp
    | LPAREN args=argList? RPAREN            # callOp
    ;

expressionList
    : items+=expression (COMMA items+=expression)*
    ;

argList
    : items+=arg (commas+=COMMA items+=arg?)*   // TwinCAT/CODESYS: `F(a := 1,)`; an empty argument elsewhere is the builder's error
    ;

// `name := value`, `name => variable` (`NOT name => variable`), `value`:
// one shape for the parser, told apart by the AST builder, so that the
// choice needs one token of lookahead.
arg
    : parts+=expression (op=(ASSIGN | ARROW) parts+=expression?)?
    ;

// ================================================================= names

// A dotted name: its parts are tokens (those of `identifier`), not rules,
// as every type name of a declaration is one (decision 0158).
qualifiedName
    : (IDENTIFIER | GET | SET | TASK | ON | WITH | READ_ONLY | READ_WRITE)
      (DOT (IDENTIFIER | GET | SET | TASK | ON | WITH | READ_ONLY | READ_WRITE))*
    ;

// Soft keywords: words with a meaning in one place that stay usable as names.
// (`action` is one too, but resolved before parsing: see
// interpreter/ast/action_keyword.h.)
identifier
    : IDENTIFIER | GET | SET | TASK | ON | WITH | READ_ONLY | READ_WRITE
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
