// The one table of diagnostic codes (see diagnostic_codes.h). Each entry is a
// page of `strun explain` and of docs/diagnostics/; keep the examples short,
// compilable in the right form, and typical of the mistake.
#include "interpreter/source/diagnostic_codes.h"

namespace strun::diagnostics {

namespace {

using K = Kind;

const std::vector<CodeInfo> kCatalogue = {
    // ---- syntax (E00xx)
    {"E0001", K::Error, "syntax error",
     "The text does not follow the grammar of Structured Text at this point. The message says what was found and what "
     "could stand there instead; the caret points at the first token that does not fit.\n\n"
     "strun reports one syntax error per line and carries on after it, so the rest of the file is still checked.",
     "x := (a + b;", "x := (a + b);"},
    {"E0002", K::Error, "missing ';'",
     "Every statement and every variable declaration ends with a semicolon. The error is reported right after the "
     "last token of the statement that lacks it, because that is where the ';' belongs.",
     "x := 1\ny := 2;", "x := 1;\ny := 2;"},
    {"E0003", K::Error, "a block is not closed",
     "IF, CASE, FOR, WHILE and REPEAT statements, and every POU, VAR block and TYPE, end with their END_ keyword "
     "(END_IF, END_CASE, END_FOR, END_WHILE, END_REPEAT, END_VAR, ...). The error names the statement that is still "
     "open and where its END_ keyword was expected.\n\n"
     "`ELSE IF` opens a second IF inside the ELSE branch, which needs its own END_IF: write `ELSIF` instead.",
     "IF x > 1 THEN\n    y := 2;\nELSE IF x < 0 THEN\n    y := 3;\nEND_IF",
     "IF x > 1 THEN\n    y := 2;\nELSIF x < 0 THEN\n    y := 3;\nEND_IF"},
    {"E0004", K::Error, "an operator of C or Java that ST does not have",
     "Structured Text has no `++`, `--`, `+=`, `-=`, `==`, `!=`, `&&`, `||` or `!`. Write `x := x + 1`, "
     "`x := x + n`, `=` for comparison, `<>` for inequality, and `AND`, `OR`, `NOT` for logic. Assignment is `:=`; a "
     "single `=` compares, and a condition (`IF x = 1 THEN`) can only compare: `IF x := 1 THEN` is an error.",
     "IF a == b && c != 0 THEN\n    n++;\nEND_IF", "IF a = b AND c <> 0 THEN\n    n := n + 1;\nEND_IF"},
    {"E0005", K::Error, "unterminated comment, string or pragma",
     "A comment `(* ... *)` or `/* ... */`, a pragma `{ ... }` or a string literal was opened and never closed. "
     "Everything after the opening belongs to it, so later lines may look fine and still not compile. A string "
     "literal must close on the line it starts.",
     "s := 'hello;\n(* a comment", "s := 'hello';\n(* a comment *)"},
    {"E0006", K::Error, "unexpected character",
     "A character that no ST token starts with (for example `$`, `\\`, `?` on its own, a control character or a "
     "byte that is not UTF-8) appears outside a comment or string.",
     "x := 3 ? 4;", "x := 3 + 4;"},
    {"E0007", K::Error, "a limit of strun is exceeded",
     "The input goes beyond one of strun's limits (tokens per file, nesting of statements, expressions or "
     "declarations, size of an array, instance or variable list). The limits are in docs/limits.md; they are far "
     "above what a PLC program needs, so the input is usually generated or broken.",
     "", ""},
    {"E0008", K::Error, "not a usable source file",
     "A FILE that strun cannot read as a project source: XML that is not well-formed, XML that is not a PLCopen TC6 "
     "project, a POU whose body is written in a language strun does not run (in TwinCAT files IL, LD, FBD, SFC, "
     "CFC), an LD, FBD or SFC body of a PLCopen file that cannot be translated (an element strun does not support, a "
     "connection to a missing element, an SFC chart without initial step or with a step that can never become active; "
     "docs/graphical.md), an IL body that cannot be translated (a jump to an undefined label, an instruction that "
     "reads the current result where no instruction sets one, a deferred operator's `(` without its `)`; decision "
     "0415), or a TwinCAT task "
     "object (.TcTTO) whose CycleTime or Priority is not a whole number or whose PouCall names no program.",
     "", ""},
    {"E0009", K::Error, "a declaration in the wrong place",
     "A declaration that is valid ST but not where it stands: VAR blocks other than VAR_GLOBAL outside a POU, a "
     "STRUCT outside TYPE, an ACTION before its POU, a body in an INTERFACE method, an access path outside "
     "VAR_ACCESS, an unknown assignment operator, VAR_GENERIC CONSTANT outside a FUNCTION_BLOCK.",
     "VAR\n    x : INT;\nEND_VAR\nPROGRAM Main\nEND_PROGRAM", "PROGRAM Main\nVAR\n    x : INT;\nEND_VAR\nEND_PROGRAM"},
    {"E0010", K::Error, "an {error} pragma",
     "The source holds a CODESYS message pragma `{error 'text'}`: its author wants compilation to stop here with "
     "that text (typically: something must be configured before the code can be used).",
     "{error 'set the number of axes in GVL_Config first'}", ""},
    // ---- names (E01xx)
    {"E0011", K::Error, "invalid literal",
     "A literal that has the form of one but no valid value: an integer beyond 64 bits, a real beyond LREAL, a date "
     "or time of day that does not exist (D#2026-02-30), a duration with an unknown unit, a string with an unknown "
     "'$' escape, a type prefix that does not make a literal (STRING#5).",
     "d := D#2026-02-30;", "d := D#2026-02-28;"},
    {"E0101", K::Error, "undeclared identifier",
     "The name is not declared where it is used: not a variable of the POU, not a global (or VAR_EXTERNAL), not an "
     "enumeration value. Check the spelling (strun suggests the closest declared name), or declare the variable in "
     "the POU's VAR block.",
     "PROGRAM Main\nVAR\n    bButton : BOOL;\nEND_VAR\nbButon := TRUE;\nEND_PROGRAM",
     "PROGRAM Main\nVAR\n    bButton : BOOL;\nEND_VAR\nbButton := TRUE;\nEND_PROGRAM"},
    {"E0102", K::Error, "unknown type",
     "The type name is neither an elementary type (INT, REAL, TIME, ...), nor a TYPE declared in the project, nor a "
     "function block, nor a block of strun's library (TON, CTU, R_TRIG, ...). Check the spelling; strun suggests the "
     "closest type name.\n\nVariables declared with an unknown type are not reported again where they are used.\n\n"
     "A name that two namespaces declare (and neither the code's own namespace, nor the top level, nor a USING "
     "of the file) is reported with both qualified names: write one of them.",
     "VAR\n    t : TIM;\nEND_VAR", "VAR\n    t : TON;\nEND_VAR"},
    {"E0103", K::Error, "no such member",
     "The structure, function block, interface or value has no member (field, input, output, method or property) "
     "of that name. strun suggests the closest member name.",
     "t(IN := start, PT := T#1s);\ndone := t.Done;", "t(IN := start, PT := T#1s);\ndone := t.Q;"},
    {"E0104", K::Error, "not a value of the enumeration",
     "The name after the enumeration's type is not one of its values. The note lists the values it has.",
     "TYPE E_Mode : (Idle, Run, Stop); END_TYPE\n...\nmode := E_Mode.Running;",
     "TYPE E_Mode : (Idle, Run, Stop); END_TYPE\n...\nmode := E_Mode.Run;"},
    {"E0105", K::Error, "undeclared function",
     "A call names no FUNCTION of the project, no function of the standard library and no conversion function. "
     "Check the spelling; strun suggests the closest function name.",
     "y := SQR(x);", "y := SQRT(x);"},
    {"E0106", K::Error, "declared twice",
     "Two declarations use the same name in the same scope (variables of one POU, members of a structure, types, "
     "POUs, globals, enumeration values, methods, program instances). Names are not case-sensitive in ST: `Speed` "
     "and `SPEED` are the same name. The note shows the first declaration.",
     "VAR\n    speed : INT;\n    Speed : REAL;\nEND_VAR", "VAR\n    speed : INT;\n    speedSetpoint : REAL;\nEND_VAR"},
    {"E0107", K::Error, "a name used as something it is not",
     "A name stands where a different kind of thing is needed: a type or POU used as a variable, a variable called "
     "like a function, a function used as a type. Calling a function block TYPE needs an instance: declare one "
     "(`t : TON;`) and call the instance (`t(IN := x, PT := T#1s);`).",
     "TON(IN := start, PT := T#1s);",
     "VAR\n    t : TON;\nEND_VAR\nt(IN := start, PT := T#1s);"},
    {"E0108", K::Error, "the name must be qualified",
     "The name is ambiguous or only reachable with its qualifier: an enumeration value that several enumerations "
     "have, where nothing says which one is meant (write `E_Mode#Run` or `E_Mode.Run`; assigned to an enumeration "
     "variable, as a CASE label of one or compared with one, the bare value is that enumeration's), or a variable "
     "of a global list with {attribute 'qualified_only'} (write `GVL.name`).",
     "n := Run;  (* n is an INT; Run is a value of two enumerations *)", "n := E_Mode.Run;"},
    {"E0109", K::Error, "not visible from here",
     "The name exists but cannot be reached from this place: an internal variable (VAR) of a function block read "
     "from outside (only VAR_INPUT and VAR_OUTPUT are visible), a PRIVATE method, or THIS/SUPER outside a function "
     "block.",
     "n := counter.count;  (* count is a VAR of the block *)", "n := counter.CV;  (* an output *)"},
    // ---- types and expressions (E02xx)
    {"E0201", K::Error, "type mismatch",
     "A value of one type is used where another type is required and ST does not convert between them implicitly "
     "(for example REAL to INT under --strict, a STRING to a number, a BOOL to an integer, a value of another "
     "enumeration). Convert explicitly with the conversion function the message names (REAL_TO_INT, TO_INT, "
     "INT_TO_STRING, ...).",
     "VAR s : STRING; n : INT; END_VAR\nn := s;", "VAR s : STRING; n : INT; END_VAR\nn := STRING_TO_INT(s);"},
    {"E0202", K::Error, "the operator does not apply to these types",
     "An operator is used with operand types it is not defined for: arithmetic on BOOL or strings, AND on numbers "
     "that are not bit strings, comparing unrelated types, MOD on REAL, NOT on an integer that is not a bit string. "
     "Convert one operand, or use the operator meant for the type.",
     "IF flag + 1 > 0 THEN", "IF BOOL_TO_INT(flag) + 1 > 0 THEN"},
    {"E0203", K::Error, "a condition must be BOOL",
     "The condition of IF, ELSIF, WHILE and REPEAT ... UNTIL must be a BOOL expression. ST does not treat numbers as "
     "truth values: compare explicitly.",
     "IF count THEN", "IF count <> 0 THEN"},
    {"E0204", K::Error, "wrong array subscript",
     "A subscript is used on a value that is not an array, with the wrong number of indices, with a non-integer "
     "index, or with a constant index outside the declared bounds.",
     "VAR a : ARRAY[1..3] OF INT; END_VAR\na[4] := 1;", "VAR a : ARRAY[1..3] OF INT; END_VAR\na[3] := 1;"},
    {"E0205", K::Error, "constant out of range",
     "A constant does not fit the type it is given to (or a length is outside what the type allows).",
     "VAR s : SINT; END_VAR\ns := SINT#300;", "VAR s : SINT; END_VAR\ns := SINT#100;"},
    {"E0206", K::Error, "not a variable",
     "A place that must be written or referred to (the left side of `:=`, an output connection, a VAR_IN_OUT "
     "argument, ADR, REF=) holds an expression, a constant or an input that cannot be written. A line with only an "
     "expression is not a statement either: assign it or call something.",
     "a + b := 3;\nx;", "c := a + b;\nx := 3;"},
    {"E0207", K::Error, "bad bit or partial access",
     "`.n`, `.%Xn`, `.%Bn`, `.%Wn` and `.%Dn` select a bit, byte, word or double word of an integer or bit-string "
     "variable; the index must exist in its type.",
     "VAR b : BYTE; END_VAR\nx := b.9;", "VAR b : BYTE; END_VAR\nx := b.7;"},
    // ---- calls (E03xx)
    {"E0301", K::Error, "wrong number of arguments",
     "A call gives more or fewer arguments than the function or block takes, leaves out an input that has no "
     "default, or leaves a VAR_IN_OUT unconnected.",
     "y := LIMIT(0, x);", "y := LIMIT(0, x, 100);"},
    {"E0302", K::Error, "no such parameter, or a parameter given twice",
     "A formal argument `name := value` names no input (or `name => var` no output) of the called POU, names one "
     "twice (by a positional argument landing on an input already named, or by name with --strict; see W0044), or mixes named and positional inputs where "
     "the function needs one or the other.",
     "t(IN := start, Time := T#1s);", "t(IN := start, PT := T#1s);"},
    {"E0303", K::Error, "input or output connected the wrong way",
     "Inputs are connected with `:=`, outputs with `=>`.",
     "t(IN := start, PT := T#1s, Q := done);", "t(IN := start, PT := T#1s, Q => done);"},
    {"E0304", K::Error, "a function-block instance used as a value",
     "A function-block instance is called as a statement and keeps its outputs; it has no return value. Call it, "
     "then read the output you need.",
     "done := t(IN := start, PT := T#1s);", "t(IN := start, PT := T#1s);\ndone := t.Q;"},
    // ---- declarations (E04xx)
    {"E0401", K::Error, "a constant is needed",
     "Array bounds, string lengths, CASE labels and VAR CONSTANT need values known when the program is compiled: "
     "literals, constants, and operators on them. So do the initial values of a FUNCTION's inputs, of VAR_STAT, "
     "of variables AT an address and of TYPE members; other initial values may name earlier variables or call "
     "functions (decision 0275).",
     "VAR n : INT; a : ARRAY[1..n] OF INT; END_VAR",
     "VAR CONSTANT N : INT := 10; END_VAR\nVAR a : ARRAY[1..N] OF INT; END_VAR"},
    {"E0402", K::Error, "wrong initial value",
     "An initial value does not match the variable: an array initialiser `[...]` for something that is not an "
     "array, more values than elements, a structure initialiser `(a := ..)` for something that is not a structure, "
     "or a value of another type.",
     "VAR a : ARRAY[1..2] OF INT := [1, 2, 3]; END_VAR", "VAR a : ARRAY[1..2] OF INT := [1, 2]; END_VAR"},
    {"E0403", K::Error, "a declaration contains itself",
     "A structure or function block contains itself by value (directly or through others), a type is defined in "
     "terms of itself, or function blocks extend each other in a cycle. Use POINTER TO or REFERENCE TO for "
     "recursive data.",
     "TYPE Node : STRUCT next : Node; END_STRUCT END_TYPE",
     "TYPE Node : STRUCT next : POINTER TO Node; END_STRUCT END_TYPE"},
    {"E0405", K::Error, "object-oriented rule broken",
     "A rule of methods, properties, interfaces and inheritance is broken: EXTENDS of something that cannot be "
     "extended or is FINAL, an instance of an ABSTRACT block, a method that does not match the interface, a "
     "missing implementation, SUPER without a parent, a property accessed the wrong way.",
     "FUNCTION_BLOCK FINAL Base\nEND_FUNCTION_BLOCK\nFUNCTION_BLOCK Derived EXTENDS Base\nEND_FUNCTION_BLOCK",
     "FUNCTION_BLOCK Base\nEND_FUNCTION_BLOCK\nFUNCTION_BLOCK Derived EXTENDS Base\nEND_FUNCTION_BLOCK"},
    {"E0406", K::Error, "VAR_EXTERNAL does not match its global",
     "A VAR_EXTERNAL must name a VAR_GLOBAL of the project, with the same type.",
     "VAR_GLOBAL g : INT; END_VAR\n...\nVAR_EXTERNAL g : REAL; END_VAR",
     "VAR_GLOBAL g : INT; END_VAR\n...\nVAR_EXTERNAL g : INT; END_VAR"},
    {"E0407", K::Error, "wrong type declaration",
     "A type is declared in a way ST does not allow: an array whose upper bound is below its lower bound, ARRAY[*] "
     "below a REFERENCE TO (decision 0428) or "
     "outside VAR_IN_OUT, a subrange or enumeration on a base type that is not an integer, a string length outside "
     "0..1048576, EXTENDS on a type that is not a structure, an enumeration value without an explicit value after "
     "the largest LINT, values in '<...>' after a block whose VAR_GENERIC CONSTANTs they do not match in number, "
     "R_EDGE or F_EDGE anywhere but on a BOOL input of a function block or program; with --strict, VAR_INPUT "
     "CONSTANT (a CODESYS extension).",
     "VAR a : ARRAY[10..1] OF INT; END_VAR", "VAR a : ARRAY[1..10] OF INT; END_VAR"},
    {"E0408", K::Error, "bad direct address",
     "An `AT %I..`, `%Q..` or `%M..` address is malformed, or does not exist on the target.",
     "VAR x AT %IX0.9 : BOOL; END_VAR", "VAR x AT %IX0.7 : BOOL; END_VAR"},
    // ---- statements (E05xx)
    {"E0501", K::Error, "EXIT or CONTINUE outside a loop",
     "EXIT leaves the innermost FOR, WHILE or REPEAT loop and CONTINUE starts its next round; outside a loop they "
     "mean nothing. To leave a POU use RETURN.",
     "IF done THEN\n    EXIT;\nEND_IF", "IF done THEN\n    RETURN;\nEND_IF"},
    {"E0502", K::Error, "wrong FOR control variable",
     "The control variable of a FOR loop must be a local integer variable that the loop may write (not an input, "
     "a constant, a REAL or a member of a structure).",
     "VAR r : REAL; END_VAR\nFOR r := 1 TO 10 DO", "VAR i : INT; END_VAR\nFOR i := 1 TO 10 DO"},
    {"E0503", K::Error, "wrong CASE label",
     "CASE labels must be constants of the selector's type (an integer or an enumeration), each value at most "
     "once, ranges written low..high.",
     "CASE n OF\n    1: x := 1;\n    1: x := 2;\nEND_CASE", "CASE n OF\n    1: x := 1;\n    2: x := 2;\nEND_CASE"},
    {"E0504", K::Error, "wrong label or JMP",
     "A JMP names a label that the POU does not define, or a label is defined twice.",
     "JMP retry;", "retry:\n    n := n + 1;\nJMP retry;"},
    // ---- configuration and tasks (E06xx)
    {"E0601", K::Error, "wrong task or configuration",
     "A CONFIGURATION, RESOURCE, TASK or PROGRAM ... WITH declaration breaks a rule of the task model or of the "
     "--target: an unknown task or task parameter, an interval, priority or watchdog outside the target's range, "
     "too many tasks of a kind, an EXTERNAL input that is not an input bit, a program that is not a PROGRAM. The "
     "rules of each target are in docs/targets.md.",
     "TASK fast (INTERVAL := T#10ms, PRIORITY := 99);", "TASK fast (INTERVAL := T#10ms, PRIORITY := 1);"},
    {"E0602", K::Error, "not available on this target",
     "A system variable, address or function exists only on another PLC family than the one selected with "
     "--target.",
     "x := %SW30;  (* only with --target m340 *)", "x := %SW30;  (* strun check --target m340 FILE *)"},
    {"W0001", K::Warning, "implicit conversion",
     "A numeric value is converted implicitly in a way IEC 61131-3 does not allow (narrowing, signed/unsigned, REAL "
     "to integer, enumeration to integer). strun accepts it like CODESYS and converts as the explicit function "
     "would; --strict makes it an error. Write the conversion function to say it is meant.",
     "VAR r : REAL; n : INT; END_VAR\nn := r;", "VAR r : REAL; n : INT; END_VAR\nn := REAL_TO_INT(r);"},
    {"W0002", K::Warning, "constant wraps",
     "A constant expression does not fit its target type and wraps around (keeps its low bits). --strict makes it "
     "an error.",
     "VAR b : BYTE; END_VAR\nb := 300;", "VAR b : BYTE; END_VAR\nb := 255;"},
    {"W0003", K::Warning, "unused variable",
     "A variable is declared and never used. Remove it, or use it.", "VAR tmp : INT; END_VAR", ""},
    {"W0004", K::Warning, "a function never assigns its result",
     "A FUNCTION with a return type returns the value assigned to its name; without an assignment it returns 0 of "
     "its type.",
     "FUNCTION Twice : INT\nVAR_INPUT x : INT; END_VAR\nx := x * 2;\nEND_FUNCTION",
     "FUNCTION Twice : INT\nVAR_INPUT x : INT; END_VAR\nTwice := x * 2;\nEND_FUNCTION"},
    {"W0005", K::Warning, "LTIME literal beyond strun's range",
     "The LTIME literal is above 2^63-1 ns (about 106751 days), the largest LTIME strun holds (TwinCAT's unsigned "
     "range goes further); it is taken as the largest value (decision 0092).",
     "t := LTIME#200000d;", "t := LTIME#100000d;"},
    {"W0006", K::Warning, "the file is not valid UTF-8",
     "The file contains bytes that are not UTF-8 (often a Latin-1 file). They are replaced by U+FFFD; in comments "
     "that does no harm, in strings it changes the text. Save the file as UTF-8.",
     "", ""},
    {"W0007", K::Warning, "a task setting is replaced by the target's",
     "The --target fixes a setting (for example the priority of an M340 task) and the value written in the TASK "
     "declaration is ignored.",
     "", ""},
    {"W0008", K::Warning, "a variable is larger than its address",
     "A variable located with AT is larger than the unit its address names (a WORD at a %IB byte address): it also "
     "covers the following addresses.",
     "VAR w AT %IB0 : WORD; END_VAR", "VAR w AT %IW0 : WORD; END_VAR"},
    {"W0009", K::Warning, "a system variable strun does not maintain",
     "The target's system variable exists, but strun does not update it: it reads 0 unless the program writes it.",
     "", ""},
    {"W0010", K::Warning, "a {warning} pragma",
     "The source holds a CODESYS message pragma `{warning 'text'}`; strun shows its text as a warning at the pragma, "
     "as CODESYS does.",
     "{warning 'temporary test values below'}", ""},
    {"W0011", K::Warning, "unreachable code",
     "Statements follow a RETURN, EXIT, CONTINUE or JMP in the same statement list, so they never run. Remove them, "
     "or put the RETURN inside an IF.",
     "IF error THEN\n    RETURN;\n    alarm := TRUE;\nEND_IF", "IF error THEN\n    alarm := TRUE;\n    RETURN;\nEND_IF"},
    {"W0012", K::Warning, "division by the constant 0",
     "The divisor of an integer `/` or MOD is the constant 0. At run time strun records DIV_BY_ZERO and divides by 1 "
     "(the outside interface's rule), which is rarely what was meant.",
     "avg := sum / 0;", "avg := sum / count;"},
    {"W0013", K::Warning, "a comparison that is always TRUE or always FALSE",
     "An unsigned integer (USINT, UINT, UDINT, ULINT) is never negative: `u < 0` is always FALSE and `u >= 0` always "
     "TRUE. Use a signed type if the value can go below zero, or compare with the value you meant.",
     "VAR level : UINT; END_VAR\nIF level < 0 THEN", "VAR level : INT; END_VAR\nIF level < 0 THEN"},
    {"W0014", K::Warning, "a function block instance is never used",
     "A PROGRAM declares a function block instance (a timer, a counter, ...) that is never called and whose outputs "
     "are never read: it does nothing. Call it, or remove it.",
     "VAR\n    delay : TON;\nEND_VAR\nlamp := start;",
     "VAR\n    delay : TON;\nEND_VAR\ndelay(IN := start, PT := T#2s);\nlamp := delay.Q;"},
    {"W0015", K::Warning, "a task INTERVAL of zero or less",
     "A cyclic task needs a positive INTERVAL. `INTERVAL := T#0ms` (or a negative duration) is no period: the task "
     "runs freewheeling, again and again without pause, and takes all the time lower-priority tasks would get. "
     "Write the period you meant, or declare the task without INTERVAL if freewheeling is meant.",
     "TASK fast (INTERVAL := T#0ms, PRIORITY := 1);", "TASK fast (INTERVAL := T#10ms, PRIORITY := 1);"},
    {"W0016", K::Warning, "a string literal longer than its target",
     "A constant string is assigned (or passed, or given as initial value) to a STRING[n] shorter than it: only the "
     "first n characters are kept. Declare the variable longer, or shorten the text.",
     "VAR msg : STRING[5]; END_VAR\nmsg := 'Motor started';", "VAR msg : STRING[20]; END_VAR\nmsg := 'Motor started';"},
    {"W0017", K::Warning, "a variable is read before it is ever written",
     "A local variable of a FUNCTION or METHOD (VAR, VAR_TEMP) without an initial value starts at 0 on every call; "
     "it keeps nothing from the previous call. Reading it before any assignment reads that 0, which is rarely what "
     "was meant: often the assignment was forgotten, or the variable should be a VAR_INPUT, a VAR_STAT, or belong to "
     "a FUNCTION_BLOCK, whose variables keep their value between calls.\n\n"
     "The check is conservative (decision 0162): statements are followed in order; an assignment inside an IF, CASE "
     "or loop counts as done for everything after that statement; a variable passed to a call as a bare argument "
     "(which a VAR_IN_OUT or ADR may write) counts as written; a POU with JMP labels is not checked. So a warning "
     "always points at a read of the initial value.",
     "FUNCTION Total : INT\nVAR_INPUT x : INT; END_VAR\nVAR sum : INT; END_VAR\nsum := sum + x;\nTotal := sum;\nEND_FUNCTION",
     "FUNCTION Total : INT\nVAR_INPUT x : INT; END_VAR\nVAR sum : INT := 0; END_VAR\nsum := sum + x;\nTotal := sum;\nEND_FUNCTION"},
    {"W0040", K::Warning, "an empty declaration",
     "A ';' right after another one in a VAR block or STRUCT (`x : INT;;`) declares nothing. It is ignored "
     "(decision 0276); remove it.",
     "VAR x : INT;; END_VAR", "VAR x : INT; END_VAR"},
    {"W0041", K::Warning, "TIME literal beyond strun's range",
     "The TIME literal is above 2^31-1 ms (T#24d20h31m23s647ms), the largest TIME strun holds: strun's TIME is "
     "signed so that durations may be negative, TwinCAT's and CODESYS' is unsigned up to T#49d17h2m47s295ms. It is "
     "taken as the largest TIME (decision 0277); use LTIME for longer durations.",
     "t := T#48d;", "t := T#24d; (* or an LTIME: LTIME#48d *)"},
    {"W0042", K::Warning, "a file of a directory argument is skipped",
     "A `.xml` file found in a directory given on the command line is not a PLCopen TC6 project (a JUnit report, "
     "another tool's settings): it is left out of the project with this warning instead of stopping the compile "
     "(decision 0208). Named on the command line itself, such a file is an error (E0008). In a Beremiz / OpenPLC "
     "Editor folder (beremiz.xml beside plc.xml) only plc.xml and the globals of its C/Python extensions are read: "
     "one warning at beremiz.xml names every other source left out, such as the ST Beremiz generated into build/ "
     "(decision 0356).",
     "", ""},
    {"W0043", K::Warning, "a part of a PLCopen export is left out",
     "A CODESYS export of a project with several devices holds one configuration per device's application; "
     "strun runs one PLC, the first configuration, and skips the others with this warning (decision 0337). "
     "Export the one application you want to run to run another.",
     "", ""},
    {"W0044", K::Warning, "a parameter given twice in one call",
     "A call names the same input (or output) twice, as `fb(Execute := TRUE, Axis := a, Execute := TRUE)`. "
     "TwinCAT compiles such calls; strun binds both in the order written, so the last value is the one the "
     "called POU sees (decision 0350). A standard function's input named twice (`LIMIT(MN := 0, MN := 1, ...)`) "
     "is the same: the last value is passed, and an earlier one that calls something is still evaluated (decision "
     "0426). With --strict it is an error: remove one of the two.",
     "fbHalt(Execute := TRUE, Axis := axis, Execute := TRUE);", "fbHalt(Execute := TRUE, Axis := axis);"},
    {"W0045", K::Warning, "inline C code is not run",
     "matiec and Beremiz (OpenPLC) copy a `{{ ... }}` block of C code into the program they compile, where it "
     "reaches the POU's variables through GetFbVar/SetFbVar. strun interprets ST and has no C compiler: the block "
     "is read as a pragma and skipped, so whatever it computes does not happen (decision 0351). Write that part "
     "in ST to have it run.",
     "{{\n  SetFbVar(OUT, GetFbVar(IN) + 1);\n}}", "OUT := IN + 1;"},
    {"ARRAY_BOUNDS", K::Runtime, "array subscript out of range (runtime)",
     "An array subscript was outside the declared bounds while the program ran. The faulty read yields 0 and the "
     "faulty write is dropped; the program-error task runs if one is configured, otherwise the PLC goes to STOP "
     "(exit 3). Check the index before using it, or fix the loop bounds.",
     "FOR i := 0 TO 10 DO\n    a[i] := 0;  (* a : ARRAY[1..10] OF INT *)\nEND_FOR",
     "FOR i := 1 TO 10 DO\n    a[i] := 0;\nEND_FOR"},
    {"CALL_DEPTH", K::Runtime, "calls nested too deeply (runtime)",
     "Calls nested deeper than 16 levels (usually a recursion without an end). The PLC goes to STOP.",
     "FUNCTION F : INT\nVAR_INPUT n : INT; END_VAR\nF := F(n + 1);\nEND_FUNCTION",
     "FUNCTION F : INT\nVAR_INPUT n : INT; END_VAR\nIF n < 5 THEN F := F(n + 1); ELSE F := n; END_IF\nEND_FUNCTION"},
    {"DIV_BY_ZERO", K::Runtime, "integer division by zero (runtime)",
     "An integer `/` or MOD had the divisor 0 while the program ran. The divisor 1 is used instead and execution "
     "continues; the entry stays in the diagnostic buffer. Test the divisor first.",
     "q := a / b;", "IF b <> 0 THEN\n    q := a / b;\nEND_IF"},
    {"IO_FAULT", K::Runtime, "a Modbus device stopped answering (runtime, --modbus-client)",
     "A device of the --modbus-client mapping did not answer (no connection, a timeout, or an exception answer); the "
     "message names the device and what failed. It is recorded once per outage: its inputs keep their last values "
     "and strun reconnects with a back-off until it answers again. The PLC keeps running (docs/modbus.md).",
     "", ""},
    {"LOG", K::Runtime, "a message the program logged (runtime)",
     "Not a fault: the program logged a message with Tc2_System ADSLOGSTR, ADSLOGDINT or ADSLOGLREAL. It is "
     "printed on stderr as `ADSLOG <PLC time> <task> <kind>: <message>` and kept in the diagnostic buffer with "
     "its kind (error, warning, hint, log from the ADSLOG_MSGTYPE_* flags). Nothing else follows.",
     "", ""},
    {"NULL_POINTER", K::Runtime, "null or invalid pointer (runtime)",
     "A null POINTER or REFERENCE was dereferenced, or a pointer that leads outside the project's memory, or a "
     "method was called through an interface that holds no instance. Like ARRAY_BOUNDS: the program-error task "
     "runs if configured, else STOP.",
     "p^ := 1;  (* p was never set *)", "p := ADR(x);\np^ := 1;"},
    {"OVERRUN", K::Runtime, "a task activation was dropped (runtime)",
     "A task was due again while its previous activation was still waiting or running; the new activation is "
     "dropped and counted in the task's overruns. Give the task a longer interval or less work, or a higher "
     "priority.",
     "", ""},
    {"SYSTEM_WATCHDOG", K::Runtime, "the controller's own watchdog stopped it (runtime, --target m241)",
     "Under --target m241: tasks of priority 0..24 held the processor without a pause (no idle time, no lower "
     "priority task) for more than 1 s, which the M241 firmware treats as an application error. Typically a "
     "cyclic task whose work takes longer than its INTERVAL: on the M241 it restarts right after writing its "
     "outputs and never lets anything else run. The PLC goes to STOP (exit 3).",
     "TASK Fast (INTERVAL := T#4ms, PRIORITY := 10);  (* its program needs 5 ms *)",
     "TASK Fast (INTERVAL := T#8ms, PRIORITY := 10);  (* period above the execution time *)"},
    {"TASK_ERROR", K::Runtime, "other runtime failure of a task (runtime)",
     "A runtime failure without a more specific code; the message says which. The PLC goes to STOP.", "", ""},
    {"WATCHDOG", K::Runtime, "a task ran longer than its watchdog (runtime)",
     "One activation of a task ran (preemptions included) longer than the task's WATCHDOG time, usually because of "
     "a loop that does not end. The activation is aborted; the execution-timeout task runs if configured, else the "
     "PLC goes to STOP.",
     "WHILE NOT done DO\n    n := n + 1;  (* done never changes *)\nEND_WHILE",
     "IF NOT done THEN\n    n := n + 1;  (* one step per cycle *)\nEND_IF"},
};

}  // namespace

const std::vector<CodeInfo>& catalogue() { return kCatalogue; }

}  // namespace strun::diagnostics
