#include "editors/lsp/project_index.h"

#include <algorithm>

#include "interpreter/project/compile.h"
#include "interpreter/sema/types.h"

namespace strun::editors::lsp {

namespace {

using sema::upper;

int codePoints(const std::string& s) {
    int n = 0;
    for (unsigned char c : s)
        if ((c & 0xC0) != 0x80) ++n;
    return n;
}

std::string exprText(const ast::Expr* e) {
    if (!e) return "";
    switch (e->kind) {
        case ast::ExprKind::Literal: return e->text.empty() ? e->typePrefix + "#" + e->valueText : e->text;
        case ast::ExprKind::Name: return e->name;
        case ast::ExprKind::Member: return exprText(e->kids[0].get()) + "." + e->name;
        case ast::ExprKind::Unary:
            return (e->op == ast::Op::Neg ? "-" : e->op == ast::Op::Not ? "NOT " : "+") + exprText(e->kids[0].get());
        case ast::ExprKind::Binary: {
            static const char* ops[] = {"+", "-", "*", "/", " MOD ", "**", "=", "<>", "<", "<=", ">", ">=", " AND ", " OR ", " XOR ", " AND_THEN ", " OR_ELSE "};
            const int k = static_cast<int>(e->op);
            return exprText(e->kids[0].get()) + (k < 17 ? ops[k] : "?") + exprText(e->kids[1].get());
        }
        default: return "...";
    }
}

std::string typeSpecText(const ast::TypeSpec* spec) {
    if (!spec) return "";
    switch (spec->kind) {
        case ast::TypeSpecKind::Named: return spec->name;
        case ast::TypeSpecKind::String:
            return std::string(spec->wide ? "WSTRING" : "STRING") + (spec->length ? "(" + exprText(spec->length.get()) + ")" : "");
        case ast::TypeSpecKind::Array: {
            std::string dims;
            for (const auto& r : spec->dims) {
                if (!dims.empty()) dims += ", ";
                dims += r.star ? "*" : exprText(r.lo.get()) + ".." + exprText(r.hi.get());
            }
            return "ARRAY[" + dims + "] OF " + typeSpecText(spec->elem.get());
        }
        case ast::TypeSpecKind::Pointer: return "POINTER TO " + typeSpecText(spec->elem.get());
        case ast::TypeSpecKind::Reference: return "REFERENCE TO " + typeSpecText(spec->elem.get());
        case ast::TypeSpecKind::Subrange:
            return typeSpecText(spec->elem.get()) + "(" + exprText(spec->lo.get()) + ".." + exprText(spec->hi.get()) + ")";
        case ast::TypeSpecKind::Enum: {
            std::string values;
            for (const auto& v : spec->enumValues) values += (values.empty() ? "" : ", ") + v.name;
            return "(" + values + ")";
        }
        case ast::TypeSpecKind::Struct: return spec->isUnion ? "UNION" : "STRUCT";
    }
    return "";
}

const char* sectionWord(ast::VarSection s) {
    switch (s) {
        case ast::VarSection::Var: return "VAR";
        case ast::VarSection::Input: return "VAR_INPUT";
        case ast::VarSection::Output: return "VAR_OUTPUT";
        case ast::VarSection::InOut: return "VAR_IN_OUT";
        case ast::VarSection::Temp: return "VAR_TEMP";
        case ast::VarSection::Stat: return "VAR_STAT";
        case ast::VarSection::Inst: return "VAR_INST";
        case ast::VarSection::Global: return "VAR_GLOBAL";
        case ast::VarSection::External: return "VAR_EXTERNAL";
        case ast::VarSection::Access: return "VAR_ACCESS";
        case ast::VarSection::Config: return "VAR_CONFIG";
    }
    return "VAR";
}

const char* pouWord(const ast::Pou& pou) {
    switch (pou.kind) {
        case ast::PouKind::Program: return "PROGRAM";
        case ast::PouKind::Function: return "FUNCTION";
        case ast::PouKind::FunctionBlock: return "FUNCTION_BLOCK";
        case ast::PouKind::Method: return pou.isAction ? "ACTION" : "METHOD";
        case ast::PouKind::Interface: return "INTERFACE";
    }
    return "";
}

bool isPouKind(SymbolKind k) {
    return k == SymbolKind::Program || k == SymbolKind::Function || k == SymbolKind::FunctionBlock || k == SymbolKind::Method ||
           k == SymbolKind::Action || k == SymbolKind::Interface || k == SymbolKind::Property;
}

ast::Loc nameOr(const ast::Loc& name, const ast::Loc& fallback) { return name.line ? name : fallback; }

}  // namespace

ProjectIndex::ProjectIndex(std::unique_ptr<SourceSet> sources, std::vector<int> userFiles, CompileLog log,
                           const sema::CompileOptions& options, project::ParsedLibrary& library,
                           std::map<int, std::shared_ptr<ast::CompilationUnit>> userUnits)
    : sources_(std::move(sources)), userFiles_(std::move(userFiles)), log_(std::move(log)), userUnits_(std::move(userUnits)) {
    userFileSet_.insert(userFiles_.begin(), userFiles_.end());
    project::CompileExtras extras;
    extras.observer = this;
    extras.modelEvenWithErrors = &model_;
    for (auto& [file, unit] : userUnits_) extras.parsed[file] = unit.get();
    std::vector<size_t> libraryUsed;
    extras.libraryUnitsUsed = &libraryUsed;
    // Nothing runs here: no call is inlined (decision 0317).
    sema::CompileOptions checkOnly = options;
    checkOnly.inlineCalls = false;
    if (auto compiled = project::compileProject(*sources_, userFiles_, log_, checkOnly, &library, nullptr, &extras)) model_ = std::move(compiled);
    // The units checked: the library's the project uses (they stay where
    // they are, in the server's ParsedLibrary), then the user's.
    std::vector<const ast::CompilationUnit*> units;
    for (size_t k : libraryUsed) units.push_back(&library.units[k]);
    for (int f : userFiles_)
        if (auto it = userUnits_.find(f); it != userUnits_.end()) units.push_back(it->second.get());
    if (model_) {
        for (sema::VarSym* g : model_->globals) globalVars_.emplace(upper(g->name), g);
        for (const auto& info : model_->pouStore)
            if (info->ast && !info->owner) topPous_.emplace(upper(info->name), info.get());
    }
    if (model_)
        for (const auto& info : model_->pouStore) {
            if (info->ast) pouInfos_[info->ast] = info.get();
            for (const auto& [name, m] : info->methods)
                if (m->ast) pouInfos_[m->ast] = m;
        }
    for (const ast::CompilationUnit* unit : units) collectUnit(*unit);
    for (const ast::CompilationUnit* unit : units)
        if (userFileSet_.count(unit->file)) resolveUnit(*unit);
    for (auto& [file, list] : occurrences_) {
        std::sort(list.begin(), list.end(), [](const Occurrence& a, const Occurrence& b) {
            return std::tie(a.line, a.col, a.declaration) < std::tie(b.line, b.col, b.declaration);
        });
        list.erase(std::unique(list.begin(), list.end(),
                               [](const Occurrence& a, const Occurrence& b) { return a.line == b.line && a.col == b.col; }),
                   list.end());
    }
    seen_.clear();
}

ProjectIndex::~ProjectIndex() = default;

void ProjectIndex::checked(const ast::Expr& e, const sema::Checked& c, const sema::PouInfo*) {
    if (c.ok) seen_[&e] = Seen{c.type, c.var};
}

// ---------------------------------------------------------------- declarations

int ProjectIndex::add(Symbol s, bool occurrence) {
    const int id = static_cast<int>(symbols_.size());
    if (s.start.line == 0) s.start = s.loc;
    if (s.end.line == 0) s.end = s.loc;
    byLoc_.emplace(std::make_tuple(s.loc.file, s.loc.line, s.loc.col), id);
    if (occurrence && s.loc.line > 0) occurrences_[s.loc.file].push_back({s.loc.line, s.loc.col, codePoints(s.name), id, true});
    symbols_.push_back(std::move(s));
    return id;
}

void ProjectIndex::collectUnit(const ast::CompilationUnit& unit) {
    for (const auto& pou : unit.pous) {
        const int id = static_cast<int>(symbols_.size());
        collectPou(*pou, -1, false);
        globalNames_.emplace(upper(pou->name), id);
    }
    for (const auto& type : unit.types) collectType(type);
    for (const auto& list : unit.globals) {
        Symbol s;
        s.kind = SymbolKind::GlobalList;
        s.name = list.nameSpace.empty() ? "VAR_GLOBAL" : list.nameSpace;
        s.loc = list.loc;
        s.detail = "global variable list";
        const int id = add(std::move(s), false);
        if (!list.nameSpace.empty()) globalNames_.emplace(upper(list.nameSpace), id);
        const size_t first = symbols_.size();
        collectVars(list.blocks, id);
        for (size_t k = first; k < symbols_.size(); ++k) {
            globalNames_.emplace(upper(symbols_[k].name), static_cast<int>(k));
            symbols_[id].end = symbols_[k].start.line > symbols_[id].end.line ? symbols_[k].start : symbols_[id].end;
        }
    }
    for (const auto& config : unit.configurations) {
        Symbol s;
        s.kind = SymbolKind::Configuration;
        s.name = config.name;
        s.loc = config.loc;
        s.detail = "CONFIGURATION " + config.name;
        const int id = add(std::move(s), false);
        const size_t first = symbols_.size();
        collectVars(config.globals, id);
        for (const auto& res : config.resources) collectVars(res.globals, id);
        for (size_t k = first; k < symbols_.size(); ++k) globalNames_.emplace(upper(symbols_[k].name), static_cast<int>(k));
        // Program instances, of a resource or of the configuration itself.
        auto addInstance = [&](const auto& p) {
            Symbol inst;
            inst.kind = SymbolKind::Variable;
            inst.name = p.instance;
            inst.loc = p.loc;
            inst.parent = id;
            inst.detail = p.typeName;
            globalNames_.emplace(upper(p.instance), add(std::move(inst), false));
        };
        for (const auto& res : config.resources)
            for (const auto& p : res.programs) addInstance(p);
        for (const auto& p : config.programs) addInstance(p);
    }
}

void ProjectIndex::collectPou(const ast::Pou& pou, int parent, bool isMethod) {
    Symbol s;
    switch (pou.kind) {
        case ast::PouKind::Program: s.kind = SymbolKind::Program; break;
        case ast::PouKind::Function: s.kind = SymbolKind::Function; break;
        case ast::PouKind::FunctionBlock: s.kind = SymbolKind::FunctionBlock; break;
        case ast::PouKind::Method: s.kind = pou.isAction ? SymbolKind::Action : SymbolKind::Method; break;
        case ast::PouKind::Interface: s.kind = SymbolKind::Interface; break;
    }
    s.name = pou.name;
    s.loc = nameOr(pou.nameLoc, pou.loc);
    s.start = pou.loc;
    s.end = pou.endLoc.line ? pou.endLoc : pou.loc;
    s.parent = parent;
    s.pou = &pou;
    std::string params;
    for (const auto& block : pou.vars) {
        if (block.section != ast::VarSection::Input && block.section != ast::VarSection::InOut && block.section != ast::VarSection::Output) continue;
        for (const auto& decl : block.vars)
            for (const auto& n : decl.names) {
                std::string p = n + " : " + typeSpecText(decl.type.get());
                if (block.section != ast::VarSection::Input) p = std::string(sectionWord(block.section)) + " " + p;
                s.params.push_back(p);
                params += (params.empty() ? "" : "; ") + p;
            }
    }
    const std::string qualified = isMethod && parent >= 0 ? symbols_[static_cast<size_t>(parent)].name + "." + pou.name : pou.name;
    s.detail = std::string(pouWord(pou)) + " " + qualified;
    if (!pou.isAction && pou.kind != ast::PouKind::Program && pou.kind != ast::PouKind::Interface) s.detail += "(" + params + ")";
    if (pou.returnType) s.detail += " : " + typeSpecText(pou.returnType.get());
    if (!pou.extends.empty() && pou.kind == ast::PouKind::FunctionBlock) s.detail += " EXTENDS " + pou.extends;
    const int id = add(std::move(s));
    collectVars(pou.vars, id);
    for (const auto& m : pou.methods) collectPou(*m, id, true);
    for (const auto& prop : pou.properties) {
        Symbol p;
        p.kind = SymbolKind::Property;
        p.name = prop.name;
        p.loc = prop.loc;
        p.parent = id;
        p.typeSpec = prop.type.get();
        p.detail = "PROPERTY " + symbols_[static_cast<size_t>(id)].name + "." + prop.name + " : " + typeSpecText(prop.type.get());
        const int pid = add(std::move(p));
        for (const auto* accessor : {prop.getter.get(), prop.setter.get()})
            if (accessor) {
                collectVars(accessor->vars, pid);
                if (accessor->endLoc.line > symbols_[static_cast<size_t>(pid)].end.line) symbols_[static_cast<size_t>(pid)].end = accessor->endLoc;
            }
    }
}

void ProjectIndex::collectVars(const std::vector<ast::VarBlock>& blocks, int parent) {
    for (const auto& block : blocks)
        for (const auto& decl : block.vars)
            for (size_t n = 0; n < decl.names.size(); ++n) {
                if (decl.names[n].find('$') != std::string::npos) continue;  // the checker's own (`inst$ENO`, decision 0358)
                Symbol s;
                s.kind = SymbolKind::Variable;
                s.name = decl.names[n];
                s.loc = n < decl.nameLocs.size() ? decl.nameLocs[n] : decl.loc;
                s.start = decl.loc;
                s.parent = parent;
                s.section = block.section;
                s.typeSpec = decl.type.get();
                s.detail = typeSpecText(decl.type.get());
                add(std::move(s));
            }
}

void ProjectIndex::collectType(const ast::TypeDecl& decl) {
    Symbol s;
    const ast::TypeSpec* spec = decl.spec.get();
    s.kind = !spec ? SymbolKind::Alias
             : spec->kind == ast::TypeSpecKind::Struct ? SymbolKind::Struct
             : spec->kind == ast::TypeSpecKind::Enum ? SymbolKind::Enum
                                                       : SymbolKind::Alias;
    s.name = decl.name;
    s.loc = nameOr(decl.nameLoc, decl.loc);
    s.start = decl.loc;
    s.typeSpec = spec;
    s.detail = "TYPE " + decl.name + " : " + (decl.extends.empty() ? "" : "EXTENDS " + decl.extends + " ") + typeSpecText(spec);
    const int id = add(std::move(s));
    globalNames_.emplace(upper(decl.name), id);
    if (!spec) return;
    if (spec->kind == ast::TypeSpecKind::Struct) {
        for (const auto& f : spec->fields)
            for (size_t n = 0; n < f.names.size(); ++n) {
                Symbol m;
                m.kind = SymbolKind::Field;
                m.name = f.names[n];
                m.loc = n < f.nameLocs.size() ? f.nameLocs[n] : f.loc;
                m.start = f.loc;
                m.parent = id;
                m.typeSpec = f.type.get();
                m.detail = typeSpecText(f.type.get());
                const int mid = add(std::move(m));
                if (symbols_[static_cast<size_t>(mid)].loc.line > symbols_[static_cast<size_t>(id)].end.line)
                    symbols_[static_cast<size_t>(id)].end = symbols_[static_cast<size_t>(mid)].loc;
            }
    } else if (spec->kind == ast::TypeSpecKind::Enum) {
        for (const auto& v : spec->enumValues) {
            Symbol m;
            m.kind = SymbolKind::EnumValue;
            m.name = v.name;
            m.loc = v.loc;
            m.parent = id;
            m.detail = decl.name + "#" + v.name + (v.value ? " := " + exprText(v.value.get()) : "");
            const int mid = add(std::move(m));
            enumValues_[upper(decl.name) + "." + upper(v.name)] = mid;
            if (v.loc.line > symbols_[static_cast<size_t>(id)].end.line) symbols_[static_cast<size_t>(id)].end = v.loc;
        }
    }
}

// ---------------------------------------------------------------- references

int ProjectIndex::symbolAt(const ast::Loc& loc) const {
    auto it = byLoc_.find(std::make_tuple(loc.file, loc.line, loc.col));
    return it == byLoc_.end() ? -1 : it->second;
}

int ProjectIndex::symbolOfVar(const sema::VarSym* v) const {
    if (!v) return -1;
    if (v->global) {
        const int g = symbolAt(v->global->loc);
        if (g >= 0) return g;
    }
    return symbolAt(v->loc);
}

const sema::PouInfo* ProjectIndex::pouInfoOf(const ast::Pou* pou) const {
    auto it = pouInfos_.find(pou);
    return it == pouInfos_.end() ? nullptr : it->second;
}

sema::VarSym* ProjectIndex::lookupVar(const sema::PouInfo* pou, const std::string& key) const {
    for (const sema::PouInfo* scope = pou; scope; scope = scope->owner) {
        for (const sema::PouInfo* p = scope; p; p = p->parent) {
            auto it = p->vars.find(key);
            if (it != p->vars.end()) return it->second;
        }
        if (scope->owner == scope) break;
    }
    auto g = globalVars_.find(key);
    return g == globalVars_.end() ? nullptr : g->second;
}

int ProjectIndex::typeSymbol(const std::string& key) const {
    auto range = globalNames_.equal_range(key);
    for (auto it = range.first; it != range.second; ++it) {
        const SymbolKind k = symbols_[static_cast<size_t>(it->second)].kind;
        if (k == SymbolKind::Struct || k == SymbolKind::Enum || k == SymbolKind::Alias || k == SymbolKind::FunctionBlock ||
            k == SymbolKind::Interface)
            return it->second;
    }
    return -1;
}

int ProjectIndex::byName(const std::string& key, const sema::PouInfo* pou) const {
    if (pou)
        if (sema::VarSym* v = lookupVar(pou, key)) {
            const int s = symbolOfVar(v);
            if (s >= 0) return s;
        }
    auto it = globalNames_.find(key);
    return it == globalNames_.end() ? -1 : it->second;
}

int ProjectIndex::memberOfType(const sema::Type* t, const std::string& key) const {
    for (int guard = 0; t && guard < 64; ++guard) {
        if (t->kind == sema::TK::Reference || t->kind == sema::TK::Pointer) {
            t = t->target;
            continue;
        }
        if (t->kind == sema::TK::Enum) {
            auto it = enumValues_.find(upper(t->name) + "." + key);
            return it == enumValues_.end() ? -1 : it->second;
        }
        for (const sema::Field& f : t->fields)
            if (upper(f.name) == key && !t->pou) {
                const int s = symbolAt(f.loc);
                if (s >= 0) return s;
            }
        for (const sema::PouInfo* p = t->pou; p; p = p->parent) {
            auto v = p->vars.find(key);
            if (v != p->vars.end()) return symbolOfVar(v->second);
            auto m = p->methods.find(key);
            if (m != p->methods.end() && m->second->ast) {
                const int s = symbolAt(nameOr(m->second->ast->nameLoc, m->second->ast->loc));
                if (s >= 0) return s;
            }
            if (p->ast)
                for (const auto& prop : p->ast->properties)
                    if (upper(prop.name) == key) return symbolAt(prop.loc);
        }
        if (t->pou) return -1;
        t = t->parent;
    }
    return -1;
}

void ProjectIndex::addReference(const ast::Loc& at, const std::string& name, int symbol) {
    if (symbol < 0 || at.line <= 0) return;
    occurrences_[at.file].push_back({at.line, at.col, codePoints(name), symbol, false});
}

void ProjectIndex::resolveUnit(const ast::CompilationUnit& unit) {
    for (const auto& pou : unit.pous) resolvePou(*pou);
    for (const auto& type : unit.types) {
        if (!type.spec) continue;
        resolveTypeSpec(type.spec.get());
        for (const auto& f : type.spec->fields) {
            resolveTypeSpec(f.type.get());
            resolveInit(f.init.get(), nullptr);
        }
        resolveInit(type.init.get(), nullptr);
    }
    auto blocks = [&](const std::vector<ast::VarBlock>& list) {
        for (const auto& block : list)
            for (const auto& decl : block.vars) {
                resolveTypeSpec(decl.type.get());
                resolveInit(decl.init.get(), nullptr);
            }
    };
    for (const auto& list : unit.globals) blocks(list.blocks);
    for (const auto& config : unit.configurations) {
        blocks(config.globals);
        for (const auto& res : config.resources) blocks(res.globals);
    }
}

void ProjectIndex::resolvePou(const ast::Pou& pou) {
    const sema::PouInfo* info = pouInfoOf(&pou);
    for (const auto& block : pou.vars)
        for (const auto& decl : block.vars) {
            resolveTypeSpec(decl.type.get());
            resolveInit(decl.init.get(), info);
        }
    resolveTypeSpec(pou.returnType.get());
    resolveStmts(pou.body, info);
    for (const auto& m : pou.methods) resolvePou(*m);
    for (const auto& prop : pou.properties) {
        resolveTypeSpec(prop.type.get());
        if (prop.getter) resolvePou(*prop.getter);
        if (prop.setter) resolvePou(*prop.setter);
    }
}

void ProjectIndex::resolveTypeSpec(const ast::TypeSpec* spec) {
    if (!spec) return;
    switch (spec->kind) {
        case ast::TypeSpecKind::Named: addReference(spec->loc, spec->name, typeSymbol(upper(spec->name))); break;
        case ast::TypeSpecKind::Array:
            for (const auto& r : spec->dims) {
                if (r.lo) resolveExpr(*r.lo, nullptr);
                if (r.hi) resolveExpr(*r.hi, nullptr);
            }
            resolveTypeSpec(spec->elem.get());
            break;
        case ast::TypeSpecKind::Pointer:
        case ast::TypeSpecKind::Reference:
        case ast::TypeSpecKind::Subrange: resolveTypeSpec(spec->elem.get()); break;
        case ast::TypeSpecKind::Struct:
            for (const auto& f : spec->fields) resolveTypeSpec(f.type.get());
            break;
        default: break;
    }
}

void ProjectIndex::resolveInit(const ast::Init* init, const sema::PouInfo* pou) {
    if (!init) return;
    if (init->expr) resolveExpr(*init->expr, pou);
    for (const auto& item : init->items) resolveInit(item.value.get(), pou);
    for (const auto& f : init->fields) resolveInit(f.value.get(), pou);
}

void ProjectIndex::resolveStmts(const ast::StmtList& list, const sema::PouInfo* pou) {
    for (const auto& s : list)
        if (s) resolveStmt(*s, pou);
}

void ProjectIndex::resolveStmt(const ast::Stmt& s, const sema::PouInfo* pou) {
    for (const ast::Expr* e : {s.target.get(), s.expr.get(), s.from.get(), s.to.get(), s.by.get()})
        if (e) resolveExpr(*e, pou);
    if (s.kind == ast::StmtKind::For && pou)
        if (sema::VarSym* v = lookupVar(pou, upper(s.name))) addReference(nameOr(s.nameLoc, s.loc), s.name, symbolOfVar(v));
    for (const auto& c : s.conds)
        if (c) resolveExpr(*c, pou);
    for (const auto& b : s.blocks) resolveStmts(b, pou);
    for (const auto& branch : s.cases) {
        for (const auto& label : branch.labels) {
            if (label.lo) resolveExpr(*label.lo, pou);
            if (label.hi) resolveExpr(*label.hi, pou);
        }
        resolveStmts(branch.body, pou);
    }
    resolveStmts(s.body, pou);
    if (s.elseBlock) resolveStmts(*s.elseBlock, pou);
}

void ProjectIndex::resolveExpr(const ast::Expr& e, const sema::PouInfo* pou) {
    auto seen = [&](const ast::Expr* x) -> const Seen* {
        auto it = seen_.find(x);
        return it == seen_.end() ? nullptr : &it->second;
    };
    switch (e.kind) {
        case ast::ExprKind::Name: {
            int sym = -1;
            if (const Seen* s = seen(&e)) {
                if (s->var) sym = symbolOfVar(s->var);
                else if (s->type && s->type->kind == sema::TK::Enum) sym = memberOfType(s->type, upper(e.name));
            }
            if (sym < 0) sym = byName(upper(e.name), pou);
            addReference(e.loc, e.name, sym);
            return;
        }
        case ast::ExprKind::Member: {
            resolveExpr(*e.kids[0], pou);
            int sym = -1;
            const Seen* s = seen(&e);
            if (s && s->var) sym = symbolOfVar(s->var);
            const std::string key = upper(e.name);
            if (sym < 0)
                if (const Seen* base = seen(e.kids[0].get()); base && base->type) sym = memberOfType(base->type, key);
            if (sym < 0 && e.kids[0]->kind == ast::ExprKind::Name) {
                const std::string baseKey = upper(e.kids[0]->name);
                auto ev = enumValues_.find(baseKey + "." + key);
                if (ev != enumValues_.end()) sym = ev->second;
                else if (auto it = globalNames_.find(baseKey); it != globalNames_.end() &&
                                                              symbols_[static_cast<size_t>(it->second)].kind == SymbolKind::GlobalList)
                    sym = byName(key, nullptr);
            }
            addReference(nameOr(e.nameLoc, e.loc), e.name, sym);
            return;
        }
        case ast::ExprKind::Call: {
            const ast::Expr& callee = *e.kids[0];
            resolveExpr(callee, pou);
            // The POU whose parameters the named arguments are.
            const sema::PouInfo* target = nullptr;
            if (const Seen* s = seen(&callee); s && s->type && s->type->pou) target = s->type->pou;
            if (!target && callee.kind == ast::ExprKind::Name)
                if (auto it = topPous_.find(upper(callee.name)); it != topPous_.end()) target = it->second;
            if (!target && callee.kind == ast::ExprKind::Member)
                if (const Seen* b = seen(callee.kids[0].get()); b && b->type) {
                    const sema::Type* t = b->type;
                    while (t && (t->kind == sema::TK::Reference || t->kind == sema::TK::Pointer)) t = t->target;
                    for (const sema::PouInfo* p = t ? t->pou : nullptr; p && !target; p = p->parent)
                        if (auto m = p->methods.find(upper(callee.name)); m != p->methods.end()) target = m->second;
                }
            for (const auto& arg : e.args) {
                if (target && !arg.name.empty())
                    for (const sema::PouInfo* p = target; p; p = p->parent)
                        if (auto v = p->vars.find(upper(arg.name)); v != p->vars.end()) {
                            addReference(arg.loc, arg.name, symbolOfVar(v->second));
                            break;
                        }
                if (arg.value) resolveExpr(*arg.value, pou);
            }
            return;
        }
        case ast::ExprKind::Literal: {
            if (e.lit != ast::LitKind::Typed || e.typePrefix.empty()) return;
            const int type = typeSymbol(upper(e.typePrefix));
            if (type < 0) return;
            addReference(e.loc, e.typePrefix, type);
            auto ev = enumValues_.find(upper(e.typePrefix) + "." + upper(e.valueText));
            if (ev != enumValues_.end())
                addReference(ast::Loc{e.loc.file, e.loc.line, e.loc.col + codePoints(e.typePrefix) + 1}, e.valueText, ev->second);
            return;
        }
        default:
            for (const auto& k : e.kids)
                if (k) resolveExpr(*k, pou);
            for (const auto& a : e.args)
                if (a.value) resolveExpr(*a.value, pou);
            return;
    }
}

// ---------------------------------------------------------------- queries

const Occurrence* ProjectIndex::occurrenceAt(int file, int line, int col) const {
    auto it = occurrences_.find(file);
    if (it == occurrences_.end()) return nullptr;
    const auto& list = it->second;
    auto pos = std::lower_bound(list.begin(), list.end(), line, [](const Occurrence& o, int l) { return o.line < l; });
    const Occurrence* best = nullptr;
    for (; pos != list.end() && pos->line == line; ++pos)
        if (col >= pos->col && col <= pos->col + pos->length) best = &*pos;  // the end too: a cursor right after a name
    return best;
}

std::vector<std::pair<int, Occurrence>> ProjectIndex::occurrencesOf(int symbol) const {
    std::vector<std::pair<int, Occurrence>> out;
    for (const auto& [file, list] : occurrences_)
        for (const auto& o : list)
            if (o.symbol == symbol) out.emplace_back(file, o);
    return out;
}

int ProjectIndex::pouAt(int file, int line) const {
    int best = -1;
    for (size_t k = 0; k < symbols_.size(); ++k) {
        const Symbol& s = symbols_[k];
        if (!s.pou || s.start.file != file || line < s.start.line || line > s.end.line) continue;
        if (best < 0 || s.start.line >= symbols_[static_cast<size_t>(best)].start.line) best = static_cast<int>(k);
    }
    return best;
}

const sema::PouInfo* ProjectIndex::pouInfoAt(int file, int line) const {
    const int p = pouAt(file, line);
    return p < 0 ? nullptr : pouInfoOf(symbols_[static_cast<size_t>(p)].pou);
}

std::vector<int> ProjectIndex::visibleAt(int file, int line) const {
    std::vector<int> out;
    const int pou = pouAt(file, line);
    if (pou >= 0) {
        // The POU's own variables, its block's (a method, an action) and those it inherits.
        std::vector<const Symbol*> scopes{&symbols_[static_cast<size_t>(pou)]};
        for (int p = symbols_[static_cast<size_t>(pou)].parent; p >= 0; p = symbols_[static_cast<size_t>(p)].parent)
            scopes.push_back(&symbols_[static_cast<size_t>(p)]);
        for (size_t k = 0; k < symbols_.size(); ++k) {
            const Symbol& s = symbols_[k];
            if (s.kind != SymbolKind::Variable || s.parent < 0) continue;
            for (const Symbol* scope : scopes)
                if (&symbols_[static_cast<size_t>(s.parent)] == scope) out.push_back(static_cast<int>(k));
        }
        if (const sema::PouInfo* info = pouInfoOf(symbols_[static_cast<size_t>(pou)].pou)) {
            const sema::PouInfo* block = info->owner ? info->owner : info;
            for (const sema::PouInfo* p = block->parent; p; p = p->parent)
                for (const auto& [name, v] : p->vars)
                    if (int s = symbolOfVar(v); s >= 0) out.push_back(s);
        }
    }
    for (const auto& [name, id] : globalNames_) {
        const Symbol& s = symbols_[static_cast<size_t>(id)];
        if (s.kind == SymbolKind::Method || s.kind == SymbolKind::Action) continue;
        out.push_back(id);
    }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

const sema::Type* ProjectIndex::typeOfName(const std::string& key, const sema::PouInfo* scope) const {
    if (sema::VarSym* v = lookupVar(scope, key)) return v->type;
    if (model_) {
        for (const auto& prog : model_->programs)
            if (upper(prog.name) == key) return prog.pou->instanceType;
        for (const auto& info : model_->pouStore)
            if (!info->owner && upper(info->name) == key && info->kind == ast::PouKind::Program) return info->instanceType;
    }
    return nullptr;
}

namespace {

// "arr[2]" -> "arr" with the number of subscripts; "x^" -> "x".
std::string plainName(const std::string& part, int& subscripts, bool& deref) {
    subscripts = 0;
    deref = false;
    std::string name;
    int depth = 0;
    for (char c : part) {
        if (c == '[') {
            if (depth++ == 0) ++subscripts;
        } else if (c == ']') {
            --depth;
        } else if (c == '^' && depth == 0) {
            deref = true;
        } else if (depth == 0 && c != ' ') {
            name.push_back(c);
        }
    }
    return upper(name);
}

const sema::Type* afterSelectors(const sema::Type* t, int subscripts, bool deref) {
    for (int k = 0; k < subscripts && t && t->kind == sema::TK::Array; ++k) t = t->elem;
    if (deref && t && (t->kind == sema::TK::Pointer || t->kind == sema::TK::Reference)) t = t->target;
    while (t && t->kind == sema::TK::Reference) t = t->target;
    return t;
}

}  // namespace

const sema::Type* ProjectIndex::typeOfChain(int file, int line, const std::vector<std::string>& chain) const {
    if (chain.empty() || !model_) return nullptr;
    const sema::PouInfo* scope = pouInfoAt(file, line);
    int subs = 0;
    bool deref = false;
    std::string first = plainName(chain[0], subs, deref);
    const sema::Type* t = nullptr;
    if ((first == "THIS" || first == "SUPER") && scope) {
        const sema::PouInfo* block = scope->owner ? scope->owner : scope;
        if (first == "SUPER") block = block->parent;
        t = block ? block->instanceType : nullptr;
        deref = false;
    } else {
        t = typeOfName(first, scope);
    }
    t = afterSelectors(t, subs, deref);
    for (size_t k = 1; k < chain.size() && t; ++k) {
        const std::string key = plainName(chain[k], subs, deref);
        const sema::Type* next = nullptr;
        for (const sema::Type* s = t; s && !next; s = s->parent) {
            if (const sema::Field* f = s->findField(key)) next = f->type;
            if (s->pou) {
                for (const sema::PouInfo* p = s->pou; p && !next; p = p->parent)
                    if (auto v = p->vars.find(key); v != p->vars.end()) next = v->second->type;
                break;
            }
        }
        t = afterSelectors(next, subs, deref);
    }
    return t;
}

void ProjectIndex::membersOfType(const sema::Type* t, bool inside, std::vector<int>& out) const {
    while (t && (t->kind == sema::TK::Reference || t->kind == sema::TK::Pointer)) t = t->target;
    if (!t) return;
    if (t->kind == sema::TK::Enum) {
        const std::string prefix = upper(t->name) + ".";
        for (auto it = enumValues_.lower_bound(prefix); it != enumValues_.end() && it->first.compare(0, prefix.size(), prefix) == 0; ++it)
            out.push_back(it->second);
        return;
    }
    if (t->pou) {
        const bool program = t->pou->kind == ast::PouKind::Program;
        for (const sema::PouInfo* p = t->pou; p; p = p->parent) {
            for (const auto& [name, v] : p->vars) {
                const auto sec = v->section;
                const bool visible = inside || program || sec == ast::VarSection::Input || sec == ast::VarSection::Output ||
                                     sec == ast::VarSection::InOut;
                if (visible && sec != ast::VarSection::Temp)
                    if (int s = symbolOfVar(v); s >= 0) out.push_back(s);
            }
            for (const auto& [name, m] : p->methods)
                if (m->ast && !m->property)
                    if (int s = symbolAt(nameOr(m->ast->nameLoc, m->ast->loc)); s >= 0) out.push_back(s);
            if (p->ast)
                for (const auto& prop : p->ast->properties)
                    if (int s = symbolAt(prop.loc); s >= 0) out.push_back(s);
        }
        return;
    }
    for (const sema::Type* s = t; s; s = s->parent)
        for (const sema::Field& f : s->fields)
            if (int id = symbolAt(f.loc); id >= 0) out.push_back(id);
}

std::vector<int> ProjectIndex::membersOfChain(int file, int line, const std::vector<std::string>& chain) const {
    std::vector<int> out;
    if (chain.empty()) return out;
    if (chain.size() == 1) {
        int subs = 0;
        bool deref = false;
        const std::string key = plainName(chain[0], subs, deref);
        // An enumeration's values, a global list's variables.
        auto range = globalNames_.equal_range(key);
        for (auto it = range.first; it != range.second; ++it) {
            const Symbol& s = symbols_[static_cast<size_t>(it->second)];
            if (s.kind == SymbolKind::Enum || s.kind == SymbolKind::GlobalList) {
                for (size_t k = 0; k < symbols_.size(); ++k)
                    if (symbols_[k].parent == it->second) out.push_back(static_cast<int>(k));
                return out;
            }
        }
    }
    const sema::Type* t = typeOfChain(file, line, chain);
    const sema::PouInfo* scope = pouInfoAt(file, line);
    const sema::PouInfo* block = scope ? (scope->owner ? scope->owner : scope) : nullptr;
    bool inside = false;
    const sema::Type* bare = t;
    while (bare && (bare->kind == sema::TK::Reference || bare->kind == sema::TK::Pointer)) bare = bare->target;
    for (const sema::PouInfo* p = block; p && bare && bare->pou; p = p->parent)
        if (p == bare->pou) inside = true;
    membersOfType(t, inside, out);
    return out;
}

int ProjectIndex::calleeOfChain(int file, int line, const std::vector<std::string>& chain) const {
    if (chain.empty()) return -1;
    int subs = 0;
    bool deref = false;
    if (chain.size() == 1) {
        const std::string key = plainName(chain[0], subs, deref);
        const sema::PouInfo* scope = pouInfoAt(file, line);
        if (sema::VarSym* v = scope || model_ ? lookupVar(scope, key) : nullptr) {
            const sema::Type* t = afterSelectors(v->type, subs, deref);
            if (t && t->pou && t->pou->ast) return symbolAt(nameOr(t->pou->ast->nameLoc, t->pou->ast->loc));
        }
        auto range = globalNames_.equal_range(key);
        for (auto it = range.first; it != range.second; ++it)
            if (symbols_[static_cast<size_t>(it->second)].pou) return it->second;
        return -1;
    }
    std::vector<std::string> base(chain.begin(), chain.end() - 1);
    const sema::Type* t = typeOfChain(file, line, base);
    const int member = memberOfType(t, plainName(chain.back(), subs, deref));
    if (member < 0) return -1;
    if (symbols_[static_cast<size_t>(member)].pou) return member;
    // A member that is an FB instance: its block type.
    const ast::TypeSpec* spec = symbols_[static_cast<size_t>(member)].typeSpec;
    if (spec && spec->kind == ast::TypeSpecKind::Named) return typeSymbol(upper(spec->name));
    return -1;
}

std::pair<int, int> ProjectIndex::compiledPosition(int file, int line, int col) const {
    if (file < 0 || file >= sources_->size()) return {line, col};
    const SourceFile& f = sources_->file(file);
    if (f.origins.empty()) return {line, col};
    int fixed = -1;
    for (size_t k = 0; k < f.origins.size(); ++k) {
        const LineOrigin& o = f.origins[k];
        if (o.line != line) continue;
        if (o.fixedCol < 0) return {static_cast<int>(k) + 1, col - o.colShift};
        if (fixed < 0) fixed = static_cast<int>(k) + 1;
    }
    return {fixed < 0 ? 0 : fixed, 1};
}

}  // namespace strun::editors::lsp
