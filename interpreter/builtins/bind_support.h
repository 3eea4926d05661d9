// Shared helpers of the standard-library bindings: matching written
// arguments to formal parameters, resolving generic (ANY_*) parameters to
// one concrete type, and wrapping a node into the Checked result the
// checker expects (folded to a constant when every argument is constant).
#pragma once

#include <initializer_list>
#include <string>
#include <vector>

#include "interpreter/sema/checker.h"
#include "interpreter/sema/node_factory.h"

namespace strun::stdlib::bind {

using sema::CallArgs;
using sema::Checked;
using sema::Checker;
using sema::Rep;
using sema::TK;
using sema::Type;
using sema::BuiltinFn;

// One formal input: its IEC name and the CODESYS alias ("IN|STR"), '|'-separated.
struct Formal {
    const char* names;
};

// Binds the written arguments of a fixed-arity function to `formals` (formal
// names in any case, positional ones in order). Reports wrong counts, unknown
// or repeated names and '=>' connections; on success `out` holds one Checked
// per formal, in formal order.
bool bindFixed(Checker& ck, CallArgs& call, std::initializer_list<Formal> formals, std::vector<Checked>& out);

// Binds an extensible function's inputs: positional, or named PREFIX<k>
// counted from `firstIndex` (IN1, IN2, ... or IN0, IN1, ...). At least `minCount`.
// `leading` fixed formals (MUX's K) come first.
bool bindExtensible(Checker& ck, CallArgs& call, std::initializer_list<Formal> leading, const char* prefix,
                    int firstIndex, size_t minCount, std::vector<Checked>& out);

// The one type all `args` are brought to, as the operators do (commonType
// pairwise). Null after an error. Strings: the kind must agree; the result is
// the kind's type with the largest maxLen of the arguments.
const Type* commonTypeOf(Checker& ck, std::vector<Checked>& args, const ast::Loc& loc, const std::string& fn);

// For inputs that are all untyped literals but give a non-constant result
// (SEL(g, 10, 20) with a variable g): the smallest type holding every value
// (USINT.. for non-negative, SINT.. otherwise, REAL when every real is exact
// in REAL, else LREAL), so the result still assigns to narrow variables.
const Type* literalType(Checker& ck, const std::vector<Checked>& args);

// Coerces every argument to `t` (strings are left as they are: their kind already matches).
bool coerceAll(Checker& ck, std::vector<Checked>& args, const Type* t, const std::string& fn);

// The REAL type an ANY_REAL parameter takes for this argument: REAL/LREAL as
// they are; integers of at most 16 bits -> REAL, wider ones and integer
// literals -> LREAL (the IEC implicit-conversion lattice); real literals -> LREAL.
const Type* realTypeFor(Checker& ck, const Checked& a);

// Wraps `node` as the call's result of type `t`. When `fold` and every
// argument is a compile-time constant of a scalar type, the call is evaluated
// now and becomes a constant, untyped again when every argument of
// `valueArgs` (default: all) was an untyped literal (SEL's G does not count).
Checked makeResult(Checker& ck, exec::Expr* node, const Type* t, const CallArgs& call, const std::vector<Checked>& args,
                   bool fold = true, const std::vector<Checked>* valueArgs = nullptr);

bool allConst(const std::vector<Checked>& args);
bool allUntyped(const std::vector<Checked>& args);

// Type-class predicates on a checked argument (untyped literals included).
bool isIntegerArg(const Checked& a);   // ANY_INT (integer types, integer literals)
bool isBitArg(const Checked& a);       // ANY_BIT without BOOL
bool isNumArg(const Checked& a);       // ANY_NUM
bool isStringArg(const Checked& a, bool wide);

// "STRING", "WSTRING" of the given kind; the result type of a string function
// of at most `maxLen` characters (clamped to 1..stdlib::kMaxStringLength).
const Type* stringResultType(Checker& ck, bool wide, int64_t maxLen);

// Fails with "FN: argument N must be ..." at the argument.
Checked argError(Checker& ck, const Checked& a, const std::string& fn, const std::string& what);

// A helper to register a name for several spellings.
void addAll(Checker& ck, std::initializer_list<const char*> names, const sema::BuiltinFn& fn);

}  // namespace strun::stdlib::bind
