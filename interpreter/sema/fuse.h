// Builds the fused nodes of interpreter/exec/fused_nodes.h where they compute
// exactly what the general nodes would (decision 0151). Every function
// returns nullptr when its pattern does not apply; the caller then builds the
// general node as before.
#pragma once

#include "interpreter/exec/call_nodes.h"
#include "interpreter/exec/fused_nodes.h"
#include "interpreter/sema/node_factory.h"

namespace strun::sema {

// a OP b in the computation representation `rep` (after arithmeticRep for
// integers) when at least one operand is a variable of the current instance
// or frame stored in exactly that representation. `b` may be null: then the
// right operand is the constant kInt (integers) or kReal (REAL/LREAL).
// Integer Div and Mod only with a constant divisor other than 0 and -1.
exec::Expr* fuseBinary(exec::NodePool& pool, exec::BinOp op, Rep rep, exec::Expr* a, exec::Expr* b, int64_t kInt = 0, double kReal = 0);

// x := x + k / x := x - k on a variable of the instance (frame = false) or
// frame, given the assigned value node.
exec::Stmt* fuseAddConstLocal(exec::NodePool& pool, Rep rep, bool frame, uint32_t off, exec::Expr* value);

// a[i] / a[i + k] on an array variable: the Index1Var with the subscript read
// inside it, when `fields.index` is a DINT or INT variable of the instance or
// frame (plus a constant); the fields are copied. nullptr otherwise.
exec::Expr* fuseIndex1(exec::NodePool& pool, Rep rep, exec::BaseKind base, const exec::Index1Fields& fields);

// place := constant, for a scalar of representation `rep`: into `place`, or,
// when place is null, at `off` in the instance, frame or pending frame (`base`).
exec::Stmt* fuseAssignConst(exec::NodePool& pool, Rep rep, exec::Expr* value, exec::Expr* place, exec::BaseKind base, uint32_t off);

// place := value where place is a scalar variable of the instance, the frame
// or the frame being bound (a call argument; an FB input member): a direct
// typed store, or its constant form.
exec::Stmt* fuseStorePending(exec::NodePool& pool, Rep rep, exec::Expr* place, exec::Expr* value);

// s := CONCAT(s, pieces...) on a STRING (wide = false) or WSTRING variable
// of the instance, frame or a fixed address whose pieces are constants or
// other variables: the in-place append (decision 0155).
exec::Stmt* fuseAppendInPlace(exec::NodePool& pool, bool wide, exec::Expr* place, uint32_t placeMaxLen, exec::Expr* value);

// The direct form of a call argument `value` stored at `dst` of the callee
// frame as a scalar of representation `rep` (decision 0154); false when the
// argument needs its statement node (aggregates, strings, references).
bool fuseArgBind(Rep rep, uint32_t dst, exec::Expr* value, exec::ArgBind& out);

// `assign` (a built assignment) as an exec::CopyLocal when it is an
// AssignLocal whose value is a variable of the instance or frame of its own
// storage type; else nullptr (decision 0409).
exec::Stmt* fuseCopyLocal(exec::NodePool& pool, exec::Stmt* assign);

// REAL/LREAL -> integer with the typed fast path; nullptr for widths it does not cover.
exec::Expr* fuseRealToInt(exec::NodePool& pool, exec::Expr* value, int bits, bool isSigned, bool truncate);

// IF cond THEN then ELSE otherwise (otherwise may be null, or the next
// ELSIF link) with the condition read by the IF itself: a fused comparison,
// a BOOL variable or a BOOL array element (decisions 0154, 0262); nullptr
// when the condition needs its node (the caller builds If1Stmt).
exec::Stmt* fuseIf(exec::NodePool& pool, exec::Expr* cond, exec::Block* then, exec::Stmt* otherwise);
// WHILE cond DO body with a fused comparison read by the loop; nullptr otherwise.
exec::Stmt* fuseWhile(exec::NodePool& pool, exec::Expr* cond, exec::Block* body);

}  // namespace strun::sema
