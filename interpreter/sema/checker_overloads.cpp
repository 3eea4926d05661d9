// Overloading by parameter types, as ST for SIMATIC AX writes it (decision
// 0362): several FUNCTIONs with one name in one namespace and different
// parameter types (AxUnit's `Assert.Equal` for every elementary type, and a
// project adding its own `Equal` for its interface or enumeration to the same
// namespace).
//
// Before anything is declared, the members of such a set are renamed apart
// ("Equal(INT, INT)"), so everything keyed by a POU's name works unchanged. A
// call of the plain name is resolved here, by the checker, to one member:
// the run-time call is the ordinary resolved call of that function, so a
// project that does not overload sees no change and an overloaded call costs
// nothing more at run time.
//
// The choice: every member whose parameters accept the arguments (by name or
// position, as any call binds them) is a candidate; an argument of exactly
// the parameter's type costs 0, an untyped literal that fits costs 1 (0 for
// DINT / LREAL, the types an untyped literal has in AX), an IEC implicit
// widening 2 plus one per doubling of the size and one for a change of
// family (SINT -> INT 3, SINT -> DINT 4, USINT -> INT 4), an integer
// becoming a REAL/LREAL (variable or literal) 8, so that an integer argument
// stays an integer first; an instance for an interface it implements or a
// base class costs 2, an enumeration as its base type 2, an input the call
// leaves out (without an initial value or a caller pragma) 1; narrowing
// never matches. The cheapest candidate wins;
// two equally cheap ones, or none, are an error naming the candidates.
#include <algorithm>
#include <limits>

#include <fmt/format.h>

#include "interpreter/sema/checker.h"
#include "stdlib/ascii_case.h"

namespace strun::sema {

bool iecWidening(const Type* from, const Type* to);  // checker_expr.cpp

namespace {

std::string typeText(const ast::TypeSpec* t) {
    if (!t) return "?";
    switch (t->kind) {
        case ast::TypeSpecKind::Named: {
            const auto dot = t->name.rfind('.');
            return dot == std::string::npos ? t->name : t->name.substr(dot + 1);
        }
        case ast::TypeSpecKind::String: return t->wide ? "WSTRING" : "STRING";
        case ast::TypeSpecKind::Array: return "ARRAY OF " + typeText(t->elem.get());
        case ast::TypeSpecKind::Pointer: return (t->refTo ? "REF_TO " : "POINTER TO ") + typeText(t->elem.get());
        case ast::TypeSpecKind::Reference: return "REF_TO " + typeText(t->elem.get());
        default: return "?";
    }
}

// The written parameter types (inputs and in-outs, then outputs as "=> T",
// in declaration order): AX tells `ToInt(str, value => x)` apart by the
// type of its output too.
std::string signatureOf(const ast::Pou& p) {
    std::string s;
    for (const bool outputs : {false, true})
    for (const auto& block : p.vars) {
        const bool output = block.section == ast::VarSection::Output;
        if (output != outputs) continue;
        if (block.section != ast::VarSection::Input && block.section != ast::VarSection::InOut && !output) continue;
        for (const auto& d : block.vars) {
            // {CallerFilePath} / {CallerLineNumber} inputs are filled by the call: not part of it.
            const bool callerInfo = std::any_of(d.pragmas.begin(), d.pragmas.end(), [](const ast::Pragma& p) {
                return upper(p.text) == "CALLERFILEPATH" || upper(p.text) == "CALLERLINENUMBER";
            });
            for (size_t n = 0; n < d.names.size() && !callerInfo; ++n) s += std::string(s.empty() ? "" : ", ") + (output ? "=> " : "") + typeText(d.type.get());
        }
    }
    return s;
}

constexpr int kNoMatch = std::numeric_limits<int>::max();

// The cost of an IEC implicit widening from `from` to `to`: 2, one more per
// doubling of the size (SINT -> INT before SINT -> DINT), one more for a
// change of family (unsigned to signed, an integer to a bit string), and an
// integer becoming a REAL/LREAL 8 (after every integer widening).
int wideningCost(const Type* from, const Type* to) {
    auto family = [](TK k) { return isSignedInt(k) ? 0 : isUnsignedInt(k) ? 1 : isBitString(k) ? 2 : isReal(k) ? 3 : 4; };
    if (isReal(to->kind) && !isReal(from->kind)) return 8;
    int cost = 2;
    for (uint32_t size = std::max<uint32_t>(from->size, 1); size < to->size; size *= 2) ++cost;
    if (family(from->kind) != family(to->kind)) ++cost;
    return cost;
}

// Whether the untyped integer literal `v` fits the integer or bit-string type `t`.
bool literalFits(int64_t v, const Type* t) {
    const unsigned bits = static_cast<unsigned>(t->size) * 8;
    if (isSignedInt(t->kind)) {
        if (bits >= 64) return true;
        const int64_t lim = int64_t(1) << (bits - 1);
        return v >= -lim && v < lim;
    }
    if (v < 0) return false;
    return bits >= 64 || static_cast<uint64_t>(v) < (uint64_t(1) << bits);
}

}  // namespace

void Checker::noteOverloads(std::vector<ast::CompilationUnit>& units) {
    struct Member {
        ast::Pou* pou;
        bool library;
        std::string signature;
    };
    std::map<std::pair<std::string, std::string>, std::vector<Member>> groups;
    for (auto& unit : units) {
        const bool library = libraryFiles_.count(unit.file) != 0;
        for (auto& p : unit.pous)
            if (p->kind == ast::PouKind::Function) groups[{upper(p->nameSpace), upper(p->name)}].push_back({p.get(), library, signatureOf(*p)});
    }
    for (auto& [key, members] : groups) {
        if (members.size() < 2) continue;  // (the METHODs follow below)
        // A user function with the parameter types of a library one replaces it
        // (as a user POU named like a library POU always did).
        std::vector<Member> kept;
        for (const Member& m : members) {
            const bool replaced = m.library && std::any_of(members.begin(), members.end(), [&](const Member& o) {
                                      return !o.library && stdlib::equalsIgnoreCase(o.signature, m.signature);
                                  });
            if (replaced) m.pou->name += "(" + m.signature + ")#library";  // declared, never reached
            else kept.push_back(m);
        }
        if (kept.size() < 2) continue;
        // Two members with the same parameter types are not overloads: the
        // duplicate declaration stays the error it always was.
        bool distinct = true;
        for (size_t i = 0; i < kept.size(); ++i)
            for (size_t j = i + 1; j < kept.size(); ++j) distinct = distinct && upper(kept[i].signature) != upper(kept[j].signature);
        if (!distinct) continue;
        OverloadSet set;
        set.nameSpace = key.first;
        for (const Member& m : kept) {
            m.pou->name += "(" + m.signature + ")";
            set.members.push_back(m.pou);
        }
        overloads_[key.second].push_back(std::move(set));
    }
    // METHODs: a name overloaded in one class is renamed in every class and
    // interface, so that an override keeps the slot of the method it overrides.
    std::vector<ast::Pou*> owners;
    for (auto& unit : units)
        for (auto& p : unit.pous)
            if (p->kind == ast::PouKind::FunctionBlock || p->kind == ast::PouKind::Interface || p->kind == ast::PouKind::Program) owners.push_back(p.get());
    for (ast::Pou* owner : owners) {
        std::map<std::string, std::vector<std::string>> byName;
        for (auto& m : owner->methods) byName[upper(m->name)].push_back(upper(signatureOf(*m)));
        for (auto& [name, sigs] : byName) {
            if (sigs.size() < 2) continue;
            std::sort(sigs.begin(), sigs.end());
            if (std::adjacent_find(sigs.begin(), sigs.end()) == sigs.end()) methodOverloads_.insert(name);
        }
    }
    if (methodOverloads_.empty()) return;
    for (ast::Pou* owner : owners)
        for (auto& m : owner->methods)
            if (methodOverloads_.count(upper(m->name))) m->name += "(" + signatureOf(*m) + ")";
}

bool Checker::callOverloadedMethod(const Checked& base, PouInfo* cls, const std::string& upperSimple, const ast::Expr& e, Checked& out) {
    if (!methodOverloads_.count(upperSimple) || !cls) return false;
    const std::string prefix = upperSimple + "(";
    std::vector<PouInfo*> owners;
    for (PouInfo* p = cls; p; p = p->parent) owners.push_back(p);
    if (cls->kind == ast::PouKind::Interface) collectInterfaces(cls, owners);
    std::vector<PouInfo*> all;
    std::set<std::string> seen;  // an override hides its base's method of the same parameter types
    for (PouInfo* p : owners)
        for (const auto& [key, m] : p->methods)
            if (key.rfind(prefix, 0) == 0 && seen.insert(key).second) all.push_back(m);
    if (all.empty()) return false;
    PouInfo* m = pickOverload(all, e);
    out = m ? methodCall(base, m, e) : bad(e.loc);
    return true;
}

bool Checker::callOverloaded(const std::string& upperSimple, const ast::Expr& e, Checked& out) {
    const auto found = overloads_.find(upperSimple);
    if (found == overloads_.end()) return false;
    // The set of the code's namespace (or one around it), else of a USING,
    // else every set of the name (names are flattened, decision 0094).
    const std::vector<OverloadSet>& sets = found->second;
    std::vector<ast::Pou*> members;
    auto take = [&](const std::string& ns) {
        for (const OverloadSet& s : sets)
            if (s.nameSpace == ns) members = s.members;
        return !members.empty();
    };
    bool chosen = false;
    for (std::string ns = nameScope_.nameSpace; !chosen && !ns.empty();) {
        chosen = take(ns);
        const auto dot = ns.rfind('.');
        ns = dot == std::string::npos ? std::string() : ns.substr(0, dot);
    }
    if (!chosen)
        if (auto usings = usingsByFile_.find(nameScope_.file); usings != usingsByFile_.end())
            for (const std::string& u : usings->second)
                if (!chosen) chosen = take(u);
    if (!chosen)
        for (const OverloadSet& s : sets) members.insert(members.end(), s.members.begin(), s.members.end());
    if (overloadInfos_.empty())
        for (const auto& p : model_.pouStore)
            if (p->ast && !p->owner) overloadInfos_[p->ast] = p.get();
    std::vector<PouInfo*> all;
    for (ast::Pou* m : members)
        if (const auto info = overloadInfos_.find(m); info != overloadInfos_.end()) all.push_back(info->second);
    PouInfo* fn = pickOverload(all, e);
    out = fn ? callUserFunction(fn, e, nullptr) : bad(e.loc);
    return true;
}

PouInfo* Checker::pickOverload(const std::vector<PouInfo*>& all, const ast::Expr& e) {
    // The arguments' types, checked once.
    std::vector<Checked> args(e.args.size());
    for (size_t k = 0; k < e.args.size(); ++k) {
        const ast::Arg& a = e.args[k];
        if (!a.value) continue;
        args[k] = checkExpr(*a.value);
        if (!args[k].ok) return nullptr;
    }
    struct Candidate {
        PouInfo* fn;
        int cost;
    };
    std::vector<Candidate> viable;
    for (PouInfo* fn : all) {
        layoutPou(fn);
        std::vector<VarSym*> inputs, outputs;
        for (VarSym* p : fn->params) (p->section != ast::VarSection::Output ? inputs : outputs).push_back(p);
        // Positional arguments past the inputs bind the outputs (decision 0361), not with --strict.
        bool allPositional = true;
        for (const auto& a : e.args) allPositional = allPositional && a.name.empty() && !a.output;
        if (allPositional && !compileOptions().strict) inputs.insert(inputs.end(), outputs.begin(), outputs.end());
        int cost = 0;
        size_t positional = 0;
        std::set<VarSym*> connected;
        for (size_t k = 0; k < e.args.size() && cost != kNoMatch; ++k) {
            const ast::Arg& a = e.args[k];
            VarSym* p = nullptr;
            if (a.name.empty()) {
                p = positional < inputs.size() ? inputs[positional] : nullptr;
                ++positional;
            } else {
                for (VarSym* q : fn->params)
                    if (stdlib::equalsIgnoreCase(q->name, a.name)) p = q;
            }
            const bool asOutput = a.output || (p && p->section == ast::VarSection::Output && a.name.empty());
            if (!p || connected.count(p) || (asOutput != (p->section == ast::VarSection::Output))) {
                cost = kNoMatch;
                break;
            }
            connected.insert(p);
            const Checked& v = args[k];
            if (asOutput) {
                // `out => x`: the output's type must go into x as it is or widened.
                const Type* out = p->type;
                const Type* into = v.type;
                if (!out || !into || !v.isPlace) cost = kNoMatch;
                else if (sameType(out, into) || (isStringType(out->kind) && out->kind == into->kind)) {}
                else if (isElementary(out->kind) && isElementary(into->kind) && iecWidening(out, into)) cost += wideningCost(out, into);
                else cost = kNoMatch;
                continue;
            }
            const Type* from = v.type;
            const Type* to = p->type;
            if (!from || !to) {
                cost = kNoMatch;
            } else if (a.value->kind == ast::ExprKind::Name && upper(a.value->name) == "NULL") {
                // NULL is a reference, never a number (strun types it as an untyped 0).
                if (to->kind != TK::Interface && to->kind != TK::Pointer && to->kind != TK::Reference) cost = kNoMatch;
            } else if (sameType(from, to) || (isStringType(from->kind) && from->kind == to->kind)) {
                // exact (a STRING of any length for a STRING parameter)
            } else if (v.isConst && from->kind == TK::String && (to->kind == TK::Char || to->kind == TK::WChar) && from->maxLen == 1) {
                cost += 1;  // a one-character literal for a CHAR: '0'
            } else if (v.untypedInt && (isInteger(to->kind) || isBitString(to->kind)) && literalFits(v.constInt, to)) {
                cost += to->kind == TK::DInt ? 0 : 1;
            } else if (v.untypedReal && isReal(to->kind)) {
                cost += to->kind == TK::LReal ? 0 : 1;
            } else if (v.untypedInt && isReal(to->kind)) {
                cost += 8;
            } else if (to->kind == TK::Array && to->flexible && from->kind == TK::Array && from->dims.size() == to->dims.size() &&
                       from->elem && to->elem && (sameType(from->elem, to->elem) || (isStringType(from->elem->kind) && from->elem->kind == to->elem->kind))) {
                cost += 1;  // an array for an ARRAY[*] of its element type
            } else if (p->byRef) {
                cost = kNoMatch;  // a VAR_IN_OUT takes its own type only
            } else if (isElementary(from->kind) && isElementary(to->kind) && iecWidening(from, to)) {
                cost += wideningCost(from, to);
            } else if (from->kind == TK::Enum && from->base && isElementary(to->kind) && !p->byRef &&
                       (sameType(from->base, to) || iecWidening(from->base, to))) {
                cost += sameType(from->base, to) ? 2 : 1 + wideningCost(from->base, to);  // an enumeration as its base type (AX: Equal on a WORD enumeration)
            } else if (to->kind == TK::Interface && (from->kind == TK::FunctionBlock || from->kind == TK::Interface) && from->pou && to->pou) {
                std::vector<PouInfo*> implemented;
                for (PouInfo* b = from->pou; b; b = b->parent) {
                    if (from->kind == TK::Interface) {
                        collectInterfaces(b, implemented);
                        break;
                    }
                    for (const auto& n : b->ast->implements) {
                        NameScopeGuard scope(*this, b->ast->nameSpace, b->ast->loc.file);
                        if (PouInfo* itf = pouNamed(n)) collectInterfaces(itf, implemented);
                    }
                }
                if (std::find(implemented.begin(), implemented.end(), to->pou) != implemented.end()) cost += 2;
                else cost = kNoMatch;
            } else if (to->kind == TK::FunctionBlock && from->kind == TK::FunctionBlock && from->pou && to->pou) {
                bool derived = false;
                for (PouInfo* b = from->pou->parent; b; b = b->parent) derived = derived || b == to->pou;
                cost = derived ? cost + 2 : kNoMatch;
            } else {
                cost = kNoMatch;
            }
        }
        for (VarSym* p : fn->params) {
            if (p->byRef && !connected.count(p)) cost = kNoMatch;  // a VAR_IN_OUT must be connected
            // An input left out that has neither an initial value nor a caller
            // pragma: a member that takes the call as written comes first.
            else if (cost != kNoMatch && p->section == ast::VarSection::Input && !connected.count(p) && !(p->decl && p->decl->init) &&
                     callerInfoOf(p) == CallerInfo::None)
                cost += 1;
        }
        if (cost != kNoMatch) viable.push_back({fn, cost});
    }
    auto listOf = [&](const std::vector<PouInfo*>& fns) {
        constexpr size_t kShown = 8;
        std::string s;
        for (size_t k = 0; k < fns.size() && k < kShown; ++k) s += (s.empty() ? "'" : ", '") + fns[k]->name + "'";
        if (fns.size() > kShown) s += fmt::format(" and {} more", fns.size() - kShown);
        return s;
    };
    const std::string& written = e.kids[0]->name;
    if (viable.empty()) {
        error(diag::E0201, e.loc, fmt::format("no overload of '{}' takes these arguments; the candidates are {}", written, listOf(all)));
        return nullptr;
    }
    int best = kNoMatch;
    for (const Candidate& c : viable) best = std::min(best, c.cost);
    std::vector<PouInfo*> tied;
    for (const Candidate& c : viable)
        if (c.cost == best) tied.push_back(c.fn);
    if (tied.size() > 1) {
        error(diag::E0201, e.loc, fmt::format("the call of '{}' is ambiguous: {} fit these arguments equally well", written, listOf(tied)));
        return nullptr;
    }
    return tied.front();
}

}  // namespace strun::sema
