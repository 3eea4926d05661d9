// Calls: user functions, function-block instances, explicit conversions and
// the standard-library functions registered by interpreter/builtins.
#include <fmt/format.h>

#include "interpreter/sema/any_argument.h"
#include "interpreter/sema/checker.h"
#include "interpreter/sema/fuse.h"
#include "interpreter/sema/parameter_named_twice.h"
#include "interpreter/sema/node_factory.h"

namespace strun::sema {

namespace {
// Type names as they appear in conversion function names.
const Type* conversionTypeName(TypeTable& types, const std::string& name) {
    if (name == "TOD") return types.elementary(TK::Tod);
    if (name == "DT") return types.elementary(TK::Dt);
    if (name == "LTOD") return types.elementary(TK::LTod);
    if (name == "LDT") return types.elementary(TK::LDt);
    const Type* t = types.byName(name);
    return t && isElementary(t->kind) ? t : nullptr;
}

struct ArgBinding {
    const ast::Arg* arg = nullptr;
    VarSym* param = nullptr;
};

// Matches written arguments to formal parameters (positional ones to the
// inputs and in-outs in declaration order). Reports every mismatch.
bool bindArguments(Checker& ck, const PouInfo* owner, const std::string& callee, const std::vector<VarSym*>& params,
                   const ast::Expr& call, std::vector<ArgBinding>& out) {
    bool ok = true;
    size_t positional = 0;
    std::vector<VarSym*> inputsInOrder;
    for (VarSym* p : params)
        if (p->section != ast::VarSection::Output) inputsInOrder.push_back(p);
    std::set<VarSym*> seen, named;  // bound, and bound by name
    // Named arguments by folded name, built once per call (not a scan per argument).
    std::unordered_map<std::string, VarSym*> byName;
    size_t positionalCount = 0;
    for (const auto& a : call.args) positionalCount += a.name.empty() ? 1 : 0;
    // A variable of unknown type is not declared: positional arguments cannot be
    // matched to the inputs, and the unknown type was the error.
    if (positionalCount > 0 && ck.hasUnresolvedVariables(owner)) return false;
    // A call of positional arguments only may go on past the inputs to the
    // outputs, in declaration order, as matiec (Beremiz, OpenPLC) binds them:
    // `pid1(TRUE, pv, sp, 0.0, kp, tr, td, cycle, xout)` (decision 0361).
    std::vector<VarSym*> outputsInOrder;
    if (positionalCount == call.args.size() && positionalCount > inputsInOrder.size() && !ck.compileOptions().strict)
        for (VarSym* p : params)
            if (p->section == ast::VarSection::Output) outputsInOrder.push_back(p);
    if (positionalCount > inputsInOrder.size() + outputsInOrder.size()) {
        ck.error(diag::E0301, call.kids[0]->loc, fmt::format("too many arguments for '{}' (it takes {})", callee, inputsInOrder.size()));
        return false;
    }
    // CODESYS: the inputs a non-formal call leaves out at the end take their
    // declared initial values, when every one of them has one
    // (`Log(msg)` of `Log(str, instance := '')`), decision 0338.
    bool trailingDefaults = positionalCount > 0 && positionalCount < inputsInOrder.size() && !ck.compileOptions().strict;
    for (size_t k = positionalCount; trailingDefaults && k < inputsInOrder.size(); ++k) {
        const VarSym* p = inputsInOrder[k];
        trailingDefaults = p->section == ast::VarSection::Input && !p->byRef && ((p->decl && p->decl->init) || callerInfoOf(p) != CallerInfo::None);
    }
    // {CallerFilePath} / {CallerLineNumber} inputs left out at the end are
    // filled by the call, in both modes (SIMATIC AX, decision 0363).
    bool trailingCallerInfo = positionalCount > 0 && positionalCount < inputsInOrder.size();
    for (size_t k = positionalCount; trailingCallerInfo && k < inputsInOrder.size(); ++k)
        trailingCallerInfo = callerInfoOf(inputsInOrder[k]) != CallerInfo::None;
    if (positionalCount > 0 && positionalCount < inputsInOrder.size() && positionalCount == call.args.size() && !trailingDefaults &&
        !trailingCallerInfo) {
        // A non-formal call lists every input (IEC 61131-3); formal calls may leave inputs out.
        ck.error(diag::E0301, call.kids[0]->loc, fmt::format("too few arguments for '{}' ({} given, it takes {})", callee, positionalCount, inputsInOrder.size()));
        return false;
    }
    bool sawNamed = false;
    for (size_t k = 0; k < call.args.size(); ++k) {
        const ast::Arg& a = call.args[k];
        VarSym* param = nullptr;
        if (a.name.empty() && sawNamed) {
            // CODESYS/TwinCAT: a positional argument after named ones binds by
            // its position in the call (`F(a := 1, b := 2, 3)`: c), decision 0204.
            if (k >= inputsInOrder.size()) {
                if (!ck.hasUnresolvedVariables(owner))
                    ck.error(diag::E0301, a.loc, fmt::format("too many arguments for '{}' (it takes {})", callee, inputsInOrder.size()));
                ok = false;
                continue;
            }
            param = inputsInOrder[k];
        } else if (a.name.empty() && positional >= inputsInOrder.size() && positional < inputsInOrder.size() + outputsInOrder.size()) {
            param = outputsInOrder[positional++ - inputsInOrder.size()];
        } else if (a.name.empty()) {
            if (positional >= inputsInOrder.size()) {
                if (!ck.hasUnresolvedVariables(owner))
                    ck.error(diag::E0301, a.loc, fmt::format("too many arguments for '{}' (it takes {})", callee, inputsInOrder.size()));
                ok = false;
                continue;
            }
            param = inputsInOrder[positional++];
        } else {
            sawNamed = true;
            std::string key = ck.canonicalParameter(owner, upper(a.name));
            if (byName.empty())
                for (VarSym* p : params) byName[upper(p->name)] = p;  // the last of a name, as the scan found it
            if (auto it = byName.find(key); it != byName.end()) param = it->second;
            if (!param && ck.isUnresolvedParameter(owner, key)) {
                ok = false;  // its unknown type was the error
                continue;
            }
            if (!param) {
                std::vector<std::string> names;
                for (const VarSym* p : params) names.push_back(p->name);
                ck.suggestName(ck.error(diag::E0302, a.loc, fmt::format("'{}' has no parameter '{}'", callee, a.name)), a.name, names);
                ok = false;
                continue;
            }
            bool isOut = param->section == ast::VarSection::Output;
            if (a.output && !isOut) {
                ck.error(diag::E0303, a.loc, fmt::format("'{}' is not an output of '{}'; connect it with ':='", a.name, callee));
                ok = false;
                continue;
            }
            if (!a.output && isOut) {
                ck.error(diag::E0303, a.loc, fmt::format("'{}' is an output of '{}'; connect it with '=>'", a.name, callee));
                ok = false;
                continue;
            }
        }
        // `x =>` with nothing after it leaves the output unconnected (TwinCAT/CODESYS
        // accept it, even naming the same output twice): it binds nothing, so it
        // neither counts as the output's binding nor clashes with one (decision 0328).
        if (a.output && !a.value) continue;
        if (seen.count(param)) {
            // Named twice: TwinCAT compiles it (pcdshub lcls-twincat-motion,
            // FB_HaltNC): both are bound in the written order, so the last value
            // is the one the callee sees; an error with --strict (decision 0350).
            // A positional argument landing on a named one stays an error (0204).
            const std::string twice = fmt::format("parameter '{}' given twice", param->name);
            if (a.name.empty() || !named.count(param)) {
                ck.error(diag::E0302, a.loc, twice);
            } else if (acceptNamedTwice(ck, a.loc, twice)) {
                out.push_back({&a, param});
                continue;
            }
            ok = false;
            continue;
        }
        seen.insert(param);
        if (!a.name.empty()) named.insert(param);
        out.push_back({&a, param});
    }
    return ok;
}
}  // namespace

std::string Checker::canonicalParameter(const PouInfo* pou, const std::string& upperName) const {
    if (!pou) return upperName;
    auto p = parameterAliases_.find(upper(pou->name));
    if (p == parameterAliases_.end()) return upperName;
    auto a = p->second.find(upperName);
    return a == p->second.end() ? upperName : a->second;
}

Checked Checker::checkConversionCall(const std::string& key, const ast::Expr& e, bool& handled) {
    handled = false;
    const Type* to = nullptr;
    const Type* from = nullptr;
    bool truncate = false;
    auto pos = key.find("_TO_");
    if (key == "TRUNC") {
        to = types().elementary(TK::DInt);
        truncate = true;
    } else if (key.rfind("TRUNC_", 0) == 0) {
        to = conversionTypeName(types(), key.substr(6));
        truncate = true;
    } else if (key.rfind("TO_", 0) == 0) {
        to = conversionTypeName(types(), key.substr(3));
    } else if (pos != std::string::npos && key.find("BCD") == std::string::npos) {
        from = conversionTypeName(types(), key.substr(0, pos));
        to = conversionTypeName(types(), key.substr(pos + 4));
        if (!from) return bad(e.loc);
    } else if (auto tp = key.find("_TRUNC_"); tp != std::string::npos) {
        from = conversionTypeName(types(), key.substr(0, tp));
        to = conversionTypeName(types(), key.substr(tp + 7));
        truncate = true;
        if (!from) return bad(e.loc);
    }
    if (!to) return bad(e.loc);
    if (isStringType(to->kind) || (from && isStringType(from->kind))) return bad(e.loc);  // string conversions: interpreter/builtins
    handled = true;
    if (e.args.size() != 1 || e.args[0].output || !e.args[0].value) {
        error(diag::E0301, e.loc, fmt::format("{} takes exactly one input", key));
        return bad(e.loc);
    }
    Checked a = checkExpr(*e.args[0].value);
    if (!a.ok) return a;
    // SIMATIC AX: a one-character literal is a CHAR where no STRING is asked
    // for, so TO_USINT('0') is its code, 48 (simatic-ax/conversion; decision 0394).
    if (!from && a.isConst && a.type->kind == TK::String && options_.axStrings && !libraryFiles_.count(e.loc.file))
        if (auto* bytes = exec::nodeCast<exec::ConstBytes>(a.node); bytes && bytes->bytes.size() >= 2 && bytes->bytes[0] != 0 && bytes->bytes[1] == 0)
            a = coerce(a, types().elementary(TK::Char), e.args[0].value->loc, key.c_str());
    if (!from && isStringType(a.type->kind)) {
        handled = false;  // TO_INT('12'): a STRING source is a stdlib conversion (interpreter/builtins)
        return bad(e.loc);
    }
    // TO_DT(pValue), TO_LTIME(pValue): a pointer converts as its address, an
    // unsigned integer of its width (TwinCAT; decision 0326).
    if (!from) a = pointerAsAddress(a, types().elementary(TK::ULInt));
    // TRUNC(i / n) of integers (struckig): IEC's implicit widening makes an
    // INT or DINT an ANY_REAL input, and its truncation is itself, so it
    // converts as the integer it is, exactly (decision 0438). LINT and ULINT
    // widen to no real type in IEC: --strict refuses them.
    if (truncate && !from && (a.untypedInt || isInteger(a.type->kind))) {
        const bool noRealWidening = !a.untypedInt && bitWidth(integerView(a.type->kind)) == 64;
        if (noRealWidening && refusedByStrict(diag::E0202, e.args[0].value->loc,
                                              fmt::format("{} needs a REAL or LREAL input; {} widens to neither (--strict)", key, typeName(a.type))))
            return bad(e.loc);
        truncate = false;
    }
    if (truncate && !(isReal(a.type->kind) || a.untypedReal)) {
        error(diag::E0202, e.args[0].value->loc, fmt::format("{} needs a REAL or LREAL input, not {}", key, typeName(a.type)));
        return bad(e.loc);
    }
    if (from) {
        if (from->kind == TK::Bool && a.type->kind != TK::Bool) {
            error(diag::E0202, e.args[0].value->loc, fmt::format("{} needs a BOOL input, not {}", key, typeName(a.type)));
            return bad(e.loc);
        }
        a = coerce(a, from, e.args[0].value->loc, key.c_str());
        if (!a.ok) return a;
        // SINT_TO_INT(s + 1): narrow arithmetic is computed at 32 bits (decision 0078);
        // the argument wraps to the parameter's width like any other argument.
        if (!a.isConst && !a.isPlace && isIntRep(from) && bitWidth(integerView(from->kind)) < 32) {
            a.node = makeIntByRep<exec::ConvIntInt>(pool(), repOf(from), a.node);
            a.node->type = from;
        }
    }
    Checked r = convert(a, to, e.loc, truncate);
    r.hasCall = a.hasCall;
    return r;
}

const BuiltinRegistry& Checker::builtinTable() const {
    if (builtinRegistrar_) {
        // Taken out first: the registrar's addBuiltin calls must not run it again.
        std::function<void(Checker&)> registrar = std::move(builtinRegistrar_);
        builtinRegistrar_ = nullptr;
        registrar(const_cast<Checker&>(*this));
    }
    return builtins_;
}

// THIS^.AssertEquals(...) in a TcUnit suite: TcUnit's assertions and test
// control are methods of FB_TestSuite, strun's are built-in functions
// (decision 0145), so a call through THIS^/SUPER^ of a name the suite has no
// method of is the built-in one.
bool Checker::isSuiteBuiltinCall(const ast::Expr& callee) {
    if (callee.kind != ast::ExprKind::Member || callee.kids[0]->kind != ast::ExprKind::Deref || !pou_) return false;
    const ast::ExprKind self = callee.kids[0]->kids[0]->kind;
    if ((self != ast::ExprKind::This && self != ast::ExprKind::Super) || !hasBuiltin(upper(callee.name))) return false;
    PouInfo* fb = pou_->owner ? pou_->owner : pou_;
    if (fb->kind != ast::PouKind::FunctionBlock || findMethod(fb, upper(callee.name))) return false;
    for (const PouInfo* p = fb; p; p = p->parent)
        if (upper(p->name) == "FB_TESTSUITE") return true;
    return false;
}

Checked Checker::checkCall(const ast::Expr& e, bool statement) {
    const ast::Expr& callee = *e.kids[0];
    // EN/ENO on a FUNCTION (not a block instance, whose EN/ENO would be its own variables).
    if (hasEnEno(e) && callee.kind == ast::ExprKind::Name) {
        const VarSym* v = lookupVar(upper(callee.name));  // `ge : BOOL` beside GE(...) still calls GE
        if (!v || !v->type || (v->type->kind != TK::FunctionBlock && v->type->kind != TK::Pointer && v->type->kind != TK::Reference &&
                               v->type->kind != TK::Interface))
            return checkEnEnoCall(e, statement);
    }
    // Lib.F(...): namespaces are flattened (names are unique in the project), so
    // the call resolves as F(...).
    ast::Expr unqualified;
    const ast::Expr* calleeName = &callee;
    if (callee.kind == ast::ExprKind::Member && isNamespace(*callee.kids[0]) && !lookupVar(upper(chainRoot(*callee.kids[0]).name))) {
        unqualified.kind = ast::ExprKind::Name;
        unqualified.loc = callee.nameLoc.line ? callee.nameLoc : callee.loc;
        unqualified.name = callee.name;
        // A contested name (decision 0325) keeps its namespace: `FILE.Delete`.
        if (std::string key = scopedKey(writtenPath(callee)); pous_.count(key)) unqualified.name = pous_.at(key)->name;
        calleeName = &unqualified;
    }
    if (isSuiteBuiltinCall(callee)) {
        unqualified.kind = ast::ExprKind::Name;
        unqualified.loc = callee.nameLoc.line ? callee.nameLoc : callee.loc;
        unqualified.name = callee.name;
        calleeName = &unqualified;
    }
    if (calleeName->kind == ast::ExprKind::Name) {
        const ast::Expr& callee = *calleeName;
        std::string key = upper(callee.name);
        const std::string pouKey = scopedKey(key);
        VarSym* v = lookupVar(key);
        // `Insert(...)` inside METHOD Insert (SIMATIC AX string-builder): the
        // method's result is no function; a function of that name is called,
        // not the method itself (decision 0397).
        bool resultNameCallsFunction = false;
        if (pou_ && pou_->kind == ast::PouKind::Method && pou_->owner && upper(pou_->name) == key && (!v || v == pou_->result)) {
            auto fn = pous_.find(pouKey);
            if ((fn != pous_.end() && fn->second->kind == ast::PouKind::Function) || overloads_.count(key) != 0) {
                v = nullptr;
                resultNameCallsFunction = true;
            }
        }
        if (v && pou_ && v == pou_->result && pous_.count(pouKey)) v = nullptr;  // recursion: F(...) inside F
        // `max : INT` (a variable) and `MAX(a, b)` (the function) live side by side:
        // a call of a name that is a plain variable calls the function of that name.
        if (v && v->type->kind != TK::FunctionBlock && v->type->kind != TK::Pointer && v->type->kind != TK::Reference &&
            v->type->kind != TK::Interface && (hasBuiltin(key) || (pous_.count(pouKey) && pous_.at(pouKey)->kind == ast::PouKind::Function)))
            v = nullptr;
        if (v) {
            if (v->type->kind == TK::FunctionBlock) {
                error(diag::E0304, e.loc, fmt::format("'{}' is a function-block instance: call it as a statement and read its outputs as {}.Q", callee.name, callee.name));
            } else {
                error(diag::E0107, callee.loc, fmt::format("'{}' is a variable, not a function", callee.name));
            }
            return bad(e.loc);
        }
        // A method of the function block being checked, called without THIS^.
        if (pou_ && !resultNameCallsFunction) {
            PouInfo* fb = pou_->owner ? pou_->owner : pou_;
            if (fb->kind == ast::PouKind::FunctionBlock || fb->kind == ast::PouKind::Program) {
                if (Checked overloaded; !methodOverloads_.empty() && methodOverloads_.count(key)) {
                    ast::Expr thisExpr;
                    thisExpr.kind = ast::ExprKind::This;
                    thisExpr.loc = e.loc;
                    Checked self = checkThis(thisExpr, true);
                    if (!self.ok) return self;
                    if (callOverloadedMethod(self, fb, key, e, overloaded)) return overloaded;  // decision 0362
                }
                if (PouInfo* m = findMethod(fb, key)) {
                    ast::Expr thisExpr;
                    thisExpr.kind = ast::ExprKind::This;
                    thisExpr.loc = e.loc;
                    Checked self = checkThis(thisExpr, true);
                    if (!self.ok) return self;
                    return methodCall(self, m, e);
                }
            }
        }
        if (key == "__POUNAME") {
            // The name of the POU the call is written in (CODESYS, TwinCAT 4026):
            // `FB.Method` in a method, `FB.Prop.Get` in an accessor, the list's
            // name in a global list's declarations (decision 0332).
            if (!e.args.empty()) {
                error(diag::E0301, e.loc, "__POUNAME takes no arguments");
                return bad(e.loc);
            }
            std::string name = declaringList_;
            if (pou_ && pou_->property)
                name = pou_->owner->name + "." + pou_->property->name + (pou_->isSetter ? ".Set" : ".Get");
            else if (pou_)
                name = pou_->owner ? pou_->owner->name + "." + pou_->name : pou_->name;
            return constantString(std::vector<uint8_t>(name.begin(), name.end()), name.size(), false, e.loc);
        }
        if (key == "ADR" || key == "REF") {
            if (e.args.size() != 1 || !e.args[0].value) {
                error(diag::E0301, e.loc, fmt::format("{} takes one variable", key));
                return bad(e.loc);
            }
            // REF(x) is the IEC 3rd-edition form of ADR(x): a REF_TO (pointer) value.
            return addressOf(*e.args[0].value, key.c_str());
        }
        if (key == "SIZEOF") {
            if (e.args.size() != 1 || !e.args[0].value) {
                error(diag::E0301, e.loc, "SIZEOF takes one argument");
                return bad(e.loc);
            }
            const Type* t = nullptr;
            const ast::Expr& a = *e.args[0].value;
            if (a.kind == ast::ExprKind::Name && a.pointerTo) {
                if (const Type* target = resolveNamedType(a.name, a.loc)) t = types().pointer(target);
                else return bad(e.loc);
            } else if (a.kind == ast::ExprKind::Name && !lookupVar(upper(a.name))) {
                t = types().byName(upper(a.name));
                const std::string typeKey = scopedKey(upper(a.name));
                if (!t && (typeDecls_.count(typeKey) || pous_.count(typeKey))) t = resolveNamedType(a.name, a.loc);
            } else if (a.kind == ast::ExprKind::Member && isNamespace(*a.kids[0]) && !lookupVar(upper(chainRoot(a).name))) {
                // SIZEOF(FsCommon.T_Generic): a type written with its library's namespace (decision 0454).
                const std::string path = writtenPath(a);
                const std::string typeKey = scopedKey(path);
                if (typeDecls_.count(typeKey) || pous_.count(typeKey) || typeDecls_.count(upper(a.name)) || pous_.count(upper(a.name)))
                    t = resolveNamedType(path, a.loc);
            }
            if (!t) {
                bool saved = suppressAutoDeref_;
                Checked v = checkExpr(a);
                suppressAutoDeref_ = saved;
                if (!v.ok) return v;
                t = v.type;
            }
            // A constant like a literal: it fits whatever integer it is assigned to.
            Checked size = constInt(t->size, types().elementary(TK::DInt), e.loc);
            size.untypedInt = true;
            return size;
        }
        if (key == "LOWER_BOUND" || key == "UPPER_BOUND") {
            if (e.args.size() != 2 || !e.args[0].value || !e.args[1].value) {
                error(diag::E0301, e.loc, fmt::format("{} takes an array and a dimension number", key));
                return bad(e.loc);
            }
            Checked a = checkExpr(*e.args[0].value);
            int64_t dim = 0;
            if (!a.ok || !constIntExpr(e.args[1].value.get(), dim, "the dimension")) return bad(e.loc);
            if (a.type->kind != TK::Array) {
                error(diag::E0201, e.args[0].value->loc, fmt::format("{} needs an array, not {}", key, typeName(a.type)));
                return bad(e.loc);
            }
            if (dim < 1 || static_cast<size_t>(dim) > a.type->dims.size()) {
                error(diag::E0204, e.args[1].value->loc, fmt::format("the array has {} dimension(s), not {}", a.type->dims.size(), dim));
                return bad(e.loc);
            }
            const bool upperBound = key == "UPPER_BOUND";
            if (!a.type->flexible) {
                const auto& d = a.type->dims[static_cast<size_t>(dim - 1)];
                return constInt(upperBound ? d.hi : d.lo, types().elementary(TK::DInt), e.loc);
            }
            Checked r;
            r.ok = true;
            r.loc = e.loc;
            r.type = types().elementary(TK::DInt);
            size_t off = 8 + 16 * static_cast<size_t>(dim - 1) + (upperBound ? 8 : 0);
            r.node = pool().make<exec::ConvIntInt<int32_t>>(pool().make<exec::FlexBound>(a.flexDesc, off));
            r.node->type = r.type;
            return r;
        }
        if (key.starts_with("__")) {
            bool handled = false;
            Checked h = heapCall(key, e, handled);
            if (handled) return h;
        }
        if (key == "__QUERYINTERFACE") {
            if (e.args.size() != 2 || !e.args[0].value || !e.args[1].value) {
                error(diag::E0301, e.loc, "__QUERYINTERFACE takes a source and a destination interface");
                return bad(e.loc);
            }
            Checked src = checkExpr(*e.args[0].value);
            Checked dst = checkExpr(*e.args[1].value);
            if (!src.ok || !dst.ok) return bad(e.loc);
            if (dst.type->kind != TK::Interface || !dst.isPlace) {
                error(diag::E0206, e.args[1].value->loc, "__QUERYINTERFACE needs an interface variable as destination");
                return bad(e.loc);
            }
            exec::Expr* addr = src.type->kind == TK::Interface ? src.node
                               : (src.type->kind == TK::FunctionBlock && src.isPlace) ? pool().make<exec::AddressOf>(src.node) : nullptr;
            if (!addr) {
                error(diag::E0405, e.args[0].value->loc, fmt::format("__QUERYINTERFACE needs an interface or an instance, not {}", typeName(src.type)));
                return bad(e.loc);
            }
            Checked r;
            r.ok = true;
            r.loc = e.loc;
            r.type = types().elementary(TK::Bool);
            r.node = pool().make<exec::QueryInterface>(pool().make<exec::TryCastInterface>(addr, dst.type->pou), dst.node);
            r.node->type = r.type;
            return r;
        }
        if (key == "__ISVALIDREF") {
            if (e.args.size() != 1 || !e.args[0].value) {
                error(diag::E0301, e.loc, "__ISVALIDREF takes one reference");
                return bad(e.loc);
            }
            bool saved = suppressAutoDeref_;
            suppressAutoDeref_ = true;
            Checked v = checkExpr(*e.args[0].value);
            suppressAutoDeref_ = saved;
            if (!v.ok) return v;
            // A VAR_IN_OUT is a reference too: valid once it is bound (TwinCAT).
            const ast::Expr& written = *e.args[0].value;
            if (written.kind == ast::ExprKind::Name && v.var && v.var->byRef && !v.var->type->flexible)
                v = inOutBinding(v.var, written.loc);
            if (v.type->kind != TK::Reference && v.type->kind != TK::Pointer && v.type->kind != TK::Interface) {
                error(diag::E0201, e.args[0].value->loc, "__ISVALIDREF needs a REFERENCE");
                return bad(e.loc);
            }
            Checked r;
            r.ok = true;
            r.loc = e.loc;
            r.type = types().elementary(TK::Bool);
            r.node = pool().make<exec::ConvToBool>(v.node, false);
            r.node->type = r.type;
            return r;
        }
        if (Checked overloaded; !overloads_.empty() && callOverloaded(key, e, overloaded)) return overloaded;  // decision 0362
        auto it = pous_.find(pouKey);
        if (it != pous_.end() && it->second->kind == ast::PouKind::Function) {
            return callUserFunction(it->second, e, nullptr);
        }
        bool handled = false;
        Checked conv = checkConversionCall(key, e, handled);
        if (handled) return conv;
        if (const BuiltinFn* b = builtinTable().find(key)) {
            CallArgs args;
            args.call = &e;
            args.name = key;
            args.loc = e.loc;
            for (const auto& a : e.args) {
                if (!a.value) {
                    error(diag::E0301, a.loc, "missing argument value");
                    return bad(e.loc);
                }
                Checked c = checkExpr(*a.value);
                if (!c.ok) return bad(e.loc);
                args.args.push_back(c);
                args.names.push_back(upper(a.name));
            }
            Checked r = (*b)(*this, args);
            if (r.ok) {
                for (const auto& a : args.args) r.hasCall = r.hasCall || a.hasCall;
                sequenceReplaced(*this, args, r);
            }
            return r;
        }
        if (it != pous_.end()) {
            if (it->second->kind == ast::PouKind::Function) return callUserFunction(it->second, e, nullptr);
            Diagnostic& d = error(diag::E0107, callee.loc, fmt::format("'{}' is a {} and cannot be called here", callee.name,
                                                          it->second->kind == ast::PouKind::Program ? "PROGRAM" : "type"));
            if (it->second->kind == ast::PouKind::FunctionBlock)
                d.withHelp(fmt::format("a function block is called through an instance: declare one in VAR ({} : {};) and call it ({}(...);)",
                                       instanceNameFor(callee.name), callee.name, instanceNameFor(callee.name)));
            return bad(e.loc);
        }
        if (isUnresolved(key)) return bad(e.loc);
        suggest(error(diag::E0105, callee.loc, fmt::format("undeclared function '{}'", callee.name)), callee.name, &Checker::functionNames);
        return bad(e.loc);
    }
    if (callee.kind == ast::ExprKind::Member) {
        Checked base = checkMethodBase(*callee.kids[0]);
        if (!base.ok) return base;
        if ((base.type->kind == TK::FunctionBlock || base.type->kind == TK::Interface) && base.type->pou) {
            if (Checked overloaded; !methodOverloads_.empty() && callOverloadedMethod(base, base.type->pou, upper(callee.name), e, overloaded))
                return overloaded;  // decision 0362
            if (PouInfo* m = findMethod(base.type->pou, upper(callee.name))) return methodCall(base, m, e);
            if (isImplicitFbInit(base.type, callee.name)) return implicitFbInitCall(base, e);
        }
        Diagnostic& d = error(diag::E0103, callee.nameLoc.line ? callee.nameLoc : callee.loc, fmt::format("'{}' is not a method of {}", callee.name, typeName(base.type)));
        if ((base.type->kind == TK::FunctionBlock || base.type->kind == TK::Interface) && base.type->pou) {
            std::vector<std::string> methods;
            for (const PouInfo* p = base.type->pou; p; p = p->parent)
                for (const auto& [key, m] : p->methods) methods.push_back(m->name);
            suggest(d, callee.name, methods);
        }
        return bad(e.loc);
    }
    error(diag::E0107, e.loc, "this cannot be called");
    return bad(e.loc);
}

// Binds a VAR_IN_OUT parameter `p` to the argument `v`: its address, or for
// ARRAY[*] its address and bounds.
exec::Stmt* Checker::bindInOut(VarSym* p, const Checked& v, exec::Expr* slot, const ast::Loc& loc) {
    if (p->constant && !(p->type->kind == TK::Array && p->type->flexible) && (!v.isPlace || (v.node && v.node->bitIndex() >= 0)))
        return bindConstantInOut(p, v, slot, loc);
    if (!v.isPlace || (v.node && v.node->bitIndex() >= 0)) {
        error(diag::E0206, loc, fmt::format("VAR_IN_OUT '{}' needs a variable, not an expression", p->name));
        return nullptr;
    }
    if (p->type->kind == TK::Array && p->type->flexible) {
        const Type* a = v.type;
        if (a->kind != TK::Array || a->dims.size() != p->type->dims.size() || !sameType(a->elem, p->type->elem)) {
            error(diag::E0201, loc, fmt::format("VAR_IN_OUT '{}' is {}, the argument is {}", p->name, typeName(p->type), typeName(a)));
            return nullptr;
        }
        auto* bind = pool().make<exec::BindArrayDesc>();
        bind->slot = slot;
        bind->place = v.node;
        bind->sourceDesc = a->flexible ? v.flexDesc : nullptr;
        for (const auto& d : a->dims) {
            bind->bounds.push_back(d.lo);
            bind->bounds.push_back(d.hi);
        }
        return bind;
    }
    // An enumeration variable for a VAR_IN_OUT of its base type (`eEnumSet : UINT`
    // given an enumeration on UINT), as TwinCAT accepts it, also for a strict
    // one: the same storage, passed by address (decision 0327).
    const bool enumOnBase = v.type->kind == TK::Enum && v.type->base && sameType(v.type->base, p->type);
    if (enumOnBase && !lenient(diag::W0001, loc, fmt::format("VAR_IN_OUT '{}' is {}, the argument is {}: passed as its base type", p->name,
                                                             typeName(p->type), typeName(v.type))))
        return nullptr;
    // A POINTER variable for a VAR_IN_OUT POINTER TO another type (`pString`
    // for `pBuffer : POINTER TO BYTE`): the same 8-byte address, as any pointer
    // assigns to any other; --strict keeps IEC's own type for VAR_IN_OUT (decision 0460).
    const bool pointerToPointer = v.type->kind == TK::Pointer && p->type->kind == TK::Pointer && !sameType(v.type, p->type) &&
                                  !isFlexibleRef(v.type) && !isFlexibleRef(p->type);
    if (pointerToPointer && refusedByStrict(diag::E0201, loc, fmt::format("VAR_IN_OUT '{}' is {}, the argument is {}: with --strict a VAR_IN_OUT "
                                                                          "takes a variable of its own type",
                                                                          p->name, typeName(p->type), typeName(v.type))))
        return nullptr;
    if (!enumOnBase && !pointerToPointer && !sameType(v.type, p->type) && !(isStringType(v.type->kind) && v.type->kind == p->type->kind) &&
        !isBlockOrExtends(v.type, p->type)) {
        error(diag::E0201, loc, fmt::format("VAR_IN_OUT '{}' is {}, the argument is {}", p->name, typeName(p->type), typeName(v.type)));
        return nullptr;
    }
    return pool().make<exec::BindAddress>(slot, v.node);
}

// VAR_IN_OUT CONSTANT given a value (a literal, an expression): the value is
// stored in a caller temporary whose address is passed (CODESYS, TwinCAT). A
// string keeps its own length, so a long literal is not cut to the formal's.
exec::Stmt* Checker::bindConstantInOut(VarSym* p, const Checked& v, exec::Expr* slot, const ast::Loc& loc) {
    Checked value = v;
    const Type* t = p->type;
    if (isStringType(v.type->kind) && v.type->kind == p->type->kind) {
        t = v.type->maxLen > p->type->maxLen ? v.type : p->type;
    } else {
        value = coerce(v, p->type, loc, "VAR_IN_OUT CONSTANT");
        if (!value.ok) return nullptr;
    }
    exec::Expr* temp = tempPlace(t);
    auto* seq = pool().make<exec::Block>();
    seq->stmts.push_back(storeTo(temp, t, value.node));
    seq->stmts.push_back(pool().make<exec::BindAddress>(slot, temp));
    return seq;
}

// `out => target` / `NOT out => target`: stores the output `src` into the caller's target.
exec::Stmt* Checker::bindOutput(const ast::Arg& arg, VarSym* p, Checked src) {
    Checked target = checkExpr(*arg.value);
    if (!target.ok) return nullptr;
    if (!target.isPlace) {
        // `fb(o => 5)`: the general "cannot be assigned" would not say why.
        error(diag::E0206, arg.value->loc, fmt::format("the output '{}' is connected with '=>' to a value: an output needs a variable that receives it",
                                          p->name))
            .withHelp(fmt::format("write '{} => someVariable', or leave the output out and read it later as instance.{}", p->name, p->name));
        return nullptr;
    }
    src.readOnly = false;
    if (arg.negated) {
        if (p->type->kind != TK::Bool) {
            error(diag::E0202, arg.loc, "NOT on an output needs a BOOL output");
            return nullptr;
        }
        src.node = pool().make<exec::NotBool>(src.node);
        src.node->type = p->type;
    }
    exec::Stmt* st = assignChecked(target, src, arg.loc);
    // Into a variable of the output's own type, from a block instance that
    // is a variable itself: a plain copy (decision 0409).
    if (exec::Stmt* copy = st ? fuseCopyLocal(pool(), st) : nullptr) return copy;
    return st;
}

exec::Stmt* Checker::bindReference(VarSym* p, const Checked& v, exec::Expr* slot, const ast::Loc& loc) {
    if (v.type->kind == TK::Reference && sameType(v.type, p->type)) return storeTo(slot, types().elementary(TK::LWord), v.node);
    // A POINTER variable for a REFERENCE TO POINTER TO another type (TcDynStringKit:
    // `_fbFree : FB_Free(THIS^._pBuffer)`, a POINTER TO STRING for `REFERENCE TO
    // POINTER TO BYTE`): the same 8-byte address, as for a VAR_IN_OUT (decision 0460).
    const Type* target = p->type->target;
    const bool pointerToPointer = v.isPlace && v.type->kind == TK::Pointer && target && target->kind == TK::Pointer &&
                                  !sameType(v.type, target) && !isFlexibleRef(v.type) && !isFlexibleRef(target);
    if (pointerToPointer && refusedByStrict(diag::E0206, loc, fmt::format("'{}' is {}, the argument is {}: with --strict a reference takes a "
                                                                          "variable of its own type",
                                                                          p->name, typeName(p->type), typeName(v.type))))
        return nullptr;
    if (!pointerToPointer && (!v.isPlace || !sameType(v.type, target))) {
        error(diag::E0206, loc, fmt::format("'{}' is {}: it needs a variable of type {}", p->name, typeName(p->type), typeName(p->type->target)));
        return nullptr;
    }
    return storeTo(slot, types().elementary(TK::LWord), pool().make<exec::AddressOf>(v.node));
}

namespace {
// A FUNCTION or METHOD declared without a result type gives the value of its
// first VAR_OUTPUT, as TwinCAT 3 does (`bOk := F_Swap(a, b)`); not with
// --strict, where it has no value (decisions 0369, 0387). Every such POU's
// code keeps that output's offset as its result (layoutPou), so a call
// dispatched to an override or through an interface reads the callee's own.
const VarSym* implicitResultOutput(const PouInfo* fn, bool strict) {
    if (fn->resultType || strict) return nullptr;
    if (fn->kind != ast::PouKind::Function && fn->kind != ast::PouKind::Method) return nullptr;
    if (fn->kind == ast::PouKind::Function && !fn->code) return nullptr;
    for (const VarSym* p : fn->params)
        if (p->section == ast::VarSection::Output) return p->byRef || !p->type ? nullptr : p;
    return nullptr;
}
}  // namespace

Checked Checker::callUserFunction(PouInfo* fn, const ast::Expr& e, exec::Expr* instance) {
    layoutPou(fn);
    std::vector<ArgBinding> bindings;
    bool ok = bindArguments(*this, fn, fn->name, fn->params, e, bindings);
    ++userCallsMade_;
    auto* call = pool().make<exec::CallPou>();
    call->callee = fn->code;
    call->instance = instance;
    call->site = site(e.loc);
    bool direct = true;  // every input has a direct form (exec::ArgBind)
    std::set<VarSym*> connected;
    for (const auto& b : bindings) {
        VarSym* p = b.param;
        connected.insert(p);
        if (!b.arg->value) continue;
        if (p->section == ast::VarSection::Output) {
            Checked src;
            src.ok = true;
            src.loc = b.arg->loc;
            src.type = p->type;
            src.node = makeByRep<exec::PendingVar>(pool(), isAggregate(p->type) ? Rep::Void : repOf(p->type), p->offset);
            src.node->type = p->type;
            if (exec::Stmt* st = bindOutput(*b.arg, p, src)) call->outputs.push_back(st);
            else ok = false;
            continue;
        }
        Checked v = checkExpr(*b.arg->value);
        if (!v.ok) { ok = false; continue; }
        if (p->byRef || p->type->kind == TK::Reference) direct = false;
        if (p->byRef) {
            exec::Expr* slot = makeByRep<exec::PendingVar>(pool(), Rep::Void, p->offset);
            if (exec::Stmt* bind = bindInOut(p, v, slot, b.arg->value->loc)) call->inputs.push_back(bind);
            else ok = false;
            continue;
        }
        exec::Expr* place = makeByRep<exec::PendingVar>(pool(), isAggregate(p->type) ? Rep::Void : repOf(p->type), p->offset);
        {
            // An input declared ANY / ANY_NUM / ... receives the argument's AnyType (decision 0302).
            std::vector<exec::Stmt*> anyBinding;
            bool anyOk = true;
            if (bindAnyArgument(*this, p, v, place, b.arg->value->loc, anyBinding, anyOk)) {
                if (!anyOk) { ok = false; continue; }
                call->inputs.insert(call->inputs.end(), anyBinding.begin(), anyBinding.end());
                direct = false;
                continue;
            }
        }
        if (p->type->kind == TK::Reference) {
            // A REFERENCE TO input is bound to the argument (like REF=).
            if (exec::Stmt* bind = bindReference(p, v, place, b.arg->value->loc)) call->inputs.push_back(bind);
            else ok = false;
            continue;
        }
        Checked cv = coerce(v, p->type, b.arg->value->loc, fmt::format("argument '{}'", p->name).c_str());
        if (!cv.ok) { ok = false; continue; }
        call->inputs.push_back(storeTo(place, p->type, cv.node));
        exec::ArgBind bind;
        if (direct && !isAggregate(p->type) && fuseArgBind(repOf(p->type), p->offset, cv.node, bind)) call->binds.push_back(bind);
        else direct = false;
    }
    bindCallerInfo(fn, connected, e.loc, call->inputs);  // {CallerFilePath} / {CallerLineNumber}
    // After an argument that did not bind (reported, or a parameter whose type is
    // unknown, reported at its declaration) an unconnected VAR_IN_OUT is a follow-on.
    const bool reportUnconnected = ok && !hasUnresolvedVariables(fn);
    for (VarSym* p : fn->params)
        if (p->byRef && !connected.count(p) && reportUnconnected) {
            error(diag::E0301, e.loc, fmt::format("{} '{}' of '{}' must be connected", p->section == ast::VarSection::Input ? "the ARRAY[*] input" : "VAR_IN_OUT", p->name, fn->name));
            ok = false;
        }
    if (!ok) return bad(e.loc);
    call->directInputs = direct && call->binds.size() == call->inputs.size();
    Checked r;
    r.ok = true;
    r.loc = e.loc;
    r.hasCall = true;
    r.type = fn->resultType ? fn->resultType : types().voidType();
    if (const VarSym* out = implicitResultOutput(fn, options_.strict)) {
        r.type = out->type;
        if (fn->code) fn->code->resultOffset = out->offset;  // a VOID function has no result of its own there
    }
    call->rep = resultRepOf(r.type);
    if (r.type != types().voidType() && isAggregate(r.type)) {
        call->resultSize = r.type->size;
        call->tempOffset = allocTemp(r.type->size);
    }
    call->type = r.type;
    r.node = call;
    if (!instance) noteInlineSite(call, fn, false, e);
    return r;
}

exec::Stmt* Checker::callFunctionBlock(Checked inst, const ast::Expr& e) {
    PouInfo* fb = inst.type->pou;
    if (!fb) return nullptr;
    layoutPou(fb);
    std::vector<ArgBinding> bindings;
    std::vector<VarSym*> params = fb->params;
    bool ok = bindArguments(*this, fb, fb->name, params, e, bindings);
    ++userCallsMade_;
    auto* call = pool().make<exec::CallFbStmt>();
    call->body = fb->code;
    call->instance = inst.node;
    call->site = site(e.loc);
    std::set<VarSym*> connected;
    // Inputs bound like a FUNCTION's arguments (exec::ArgBind, decision 0267):
    // only when the instance is a plain variable (its address costs nothing
    // and cannot fault, so taking it before the inputs changes nothing) and
    // no input calls anything (no side effect can tell the order apart).
    bool direct = !e.kids.empty() && e.kids[0]->kind == ast::ExprKind::Name && !inst.hasCall && inst.var && !inst.var->byRef &&
                  inst.var->type == inst.type;  // not a VAR_IN_OUT or REFERENCE TO (a dereference may fault)
    for (const auto& b : bindings) {
        VarSym* p = b.param;
        connected.insert(p);
        if (!b.arg->value) continue;
        Checked member = memberOf(inst, p->name, b.arg->loc);
        if (!member.ok) { ok = false; continue; }
        if (p->section == ast::VarSection::Output) {
            if (exec::Stmt* st = bindOutput(*b.arg, p, member)) call->outputs.push_back(st);
            else ok = false;
            continue;
        }
        Checked v = checkExpr(*b.arg->value);
        if (!v.ok) { ok = false; continue; }
        if (p->byRef || p->type->kind == TK::Reference) direct = false;
        if (p->byRef) {
            const Field* f = inst.type->findField(upper(p->name));
            exec::Expr* slot = pool().make<exec::OffsetPlace>(inst.node, f ? f->offset : 0);
            if (exec::Stmt* bind = bindInOut(p, v, slot, b.arg->value->loc)) call->inputs.push_back(bind);
            else ok = false;
            continue;
        }
        if (p->type->kind == TK::Reference) {
            bool saved = suppressAutoDeref_;
            suppressAutoDeref_ = true;
            Checked raw = memberOf(inst, p->name, b.arg->loc);
            suppressAutoDeref_ = saved;
            if (!raw.ok) { ok = false; continue; }
            if (exec::Stmt* bind = bindReference(p, v, raw.node, b.arg->value->loc)) call->inputs.push_back(bind);
            else ok = false;
            continue;
        }
        member.readOnly = false;
        exec::Stmt* st = assignChecked(member, v, b.arg->loc);
        if (st) call->inputs.push_back(st);
        else ok = false;
        // The direct form stores what the assignment stores: the value of the
        // parameter's own type, or a literal (checked against the input's
        // range by the assignment) converted to it.
        const Field* field = inst.type->findField(upper(p->name));
        const bool literal = v.isConst && (exec::nodeCast<exec::ConstInt>(v.node) || exec::nodeCast<exec::ConstReal>(v.node));
        const bool asIs = sameType(v.type, p->type) || (literal && v.untypedInt && isInteger(p->type->kind)) ||
                          (literal && (v.untypedInt || v.untypedReal) && isReal(p->type->kind));
        exec::ArgBind bind;
        if (direct && st && field && !v.hasCall && asIs && !isAggregate(p->type) && fuseArgBind(repOf(p->type), field->offset, v.node, bind))
            call->binds.push_back(bind);
        else direct = false;
    }
    call->directInputs = direct && call->binds.size() == call->inputs.size();
    for (VarSym* p : params)
        if (p->byRef && !connected.count(p)) {
            // An unconnected VAR_IN_OUT of an FB keeps its previous binding (CODESYS); only the first call must bind it.
        }
    if (!ok) return nullptr;
    // Through a pointer, a reference or a VAR_IN_OUT the instance may be of a
    // block derived from `fb`: then its own body runs (decision 0314).
    // SUPER^() runs the base's body itself.
    const bool exactType = inst.var && !inst.var->byRef && inst.var->type == inst.type;
    const ast::Expr* callee = e.kids.empty() ? nullptr : e.kids[0].get();
    const bool super = callee && callee->kind == ast::ExprKind::Deref && !callee->kids.empty() && callee->kids[0] &&
                       callee->kids[0]->kind == ast::ExprKind::Super;
    if (!exactType && !super && isExtended(fb)) {
        auto* dispatch = pool().make<exec::CallFbDispatchStmt>();
        dispatch->body = call->body;
        dispatch->instance = call->instance;
        dispatch->inputs = std::move(call->inputs);
        dispatch->binds = std::move(call->binds);
        dispatch->directInputs = call->directInputs;
        dispatch->outputs = std::move(call->outputs);
        dispatch->site = call->site;
        return dispatch;
    }
    if (exactType) noteInlineSite(call, fb);  // the body that runs is fb's own (decision 0317)
    return call;
}

bool Checker::isExtended(const PouInfo* fb) {
    if (!extendedKnown_) {
        for (const PouInfo* p : pouOrder_)
            if (p->parent) extendedBlocks_.insert(p->parent);
        extendedKnown_ = true;
    }
    return extendedBlocks_.count(fb) != 0;
}

}  // namespace strun::sema
