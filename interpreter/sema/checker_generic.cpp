// Blocks with VAR_GENERIC CONSTANT (TwinCAT 4026 / CODESYS, decision 0312):
// `fb : FB_Buffer<100>;` is an instance of FB_Buffer whose generic constants
// have the values in angle brackets. Each distinct set of values is one
// specialisation: a copy of the block's declaration (its methods and
// properties too) named `FB_Buffer<100>`, whose generic constants are plain
// constants with those values, declared, laid out and checked like any block.
// The values are constant expressions of the scope that declares the
// instance, so `FB_X<(2 * cSize)>` may name the declaring POU's constants.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include "interpreter/ast/ast_clone.h"
#include "interpreter/ast/synthesized_expr.h"
#include "interpreter/sema/checker.h"

namespace strun::sema {

namespace {

size_t genericConstantCount(const ast::Pou& pou) {
    size_t n = 0;
    for (const auto& block : pou.vars)
        if (block.generic)
            for (const auto& decl : block.vars) n += decl.names.size();
    return n;
}

}  // namespace

PouInfo* Checker::specialise(const std::string& name, const std::vector<ast::ExprPtr>& args, const ast::Loc& loc) {
    if (declDepthExceeded_) return nullptr;  // reported: a block nesting itself with ever new values stops here
    PouInfo* generic = pouNamed(name);
    if (!generic || generic->kind != ast::PouKind::FunctionBlock || !generic->ast) {
        error(diag::E0102, loc, fmt::format("unknown function block '{}' (only a FUNCTION_BLOCK takes values in '<...>')", name));
        return nullptr;
    }
    const size_t expected = genericConstantCount(*generic->ast);
    if (expected == 0) {
        error(diag::E0407, loc, fmt::format("'{}' has no VAR_GENERIC CONSTANT to give the values in '<...>' to", generic->name));
        return nullptr;
    }
    if (args.size() != expected) {
        error(diag::E0407, loc,
              fmt::format("'{}' has {} VAR_GENERIC CONSTANT{}, but {} value{} {} given", generic->name, expected,
                          expected == 1 ? "" : "S", args.size(), args.size() == 1 ? "" : "s", args.size() == 1 ? "is" : "are"));
        return nullptr;
    }
    std::vector<int64_t> values;
    for (const auto& arg : args) {
        int64_t v = 0;
        if (!arg || !constIntExpr(arg.get(), v, "the value of a VAR_GENERIC CONSTANT")) return nullptr;
        values.push_back(v);
    }
    const std::string specName = fmt::format("{}<{}>", generic->name, fmt::join(values, ","));
    if (auto known = pous_.find(upper(specName)); known != pous_.end()) return known->second;
    if (genericCopies_.size() >= kMaxSpecialisations) {
        if (!specialisationLimitReported_)
            error(diag::E0007, loc, fmt::format("more than {} specialisations of blocks with VAR_GENERIC CONSTANT", kMaxSpecialisations));
        specialisationLimitReported_ = true;
        return nullptr;
    }
    std::unique_ptr<ast::Pou> copy = ast::clonePou(*generic->ast);
    copy->name = specName;
    size_t next = 0;
    for (auto& block : copy->vars) {
        if (!block.generic) continue;
        // One declaration per name: `a, b : INT;` gets a value each.
        std::vector<ast::VarDecl> split;
        for (const ast::VarDecl& decl : block.vars)
            for (size_t n = 0; n < decl.names.size(); ++n) {
                ast::VarDecl one = ast::cloneVarDecl(decl);
                one.names = {decl.names[n]};
                one.nameLocs = n < decl.nameLocs.size() ? std::vector<ast::Loc>{decl.nameLocs[n]} : std::vector<ast::Loc>{};
                one.init = std::make_unique<ast::Init>();
                one.init->loc = args[next]->loc;
                one.init->expr = ast::integerExpr(values[next], args[next]->loc);
                ++next;
                split.push_back(std::move(one));
            }
        block.vars = std::move(split);
    }
    ast::Pou* raw = copy.get();
    genericCopies_.push_back(std::move(copy));
    declarePou(raw, nullptr);
    auto made = pous_.find(upper(specName));
    return made == pous_.end() ? nullptr : made->second;
}

const Type* Checker::specialisedInstanceType(const ast::TypeSpec& spec) {
    PouInfo* p = specialise(spec.name, spec.genericArgs, spec.loc);
    if (!p) return nullptr;
    layoutPou(p);
    return p->instanceType;
}

}  // namespace strun::sema
