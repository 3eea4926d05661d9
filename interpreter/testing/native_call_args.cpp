#include "interpreter/testing/native_call_args.h"

#include <fmt/format.h>

#include "interpreter/sema/parameter_named_twice.h"

namespace strun::testing::native_call {

using sema::CallArgs;
using sema::Checked;
using sema::Checker;
using sema::TK;

std::string written(const CallArgs& call) {
    if (call.call && !call.call->kids.empty() && !call.call->kids[0]->name.empty()) return call.call->kids[0]->name;
    return call.name;
}

// TcUnit's inputs a call leaves out keep their default (Message '', Delta 0).
bool bindArgs(Checker& ck, CallArgs& call, std::initializer_list<Param> params, std::vector<Checked>& out) {
    const size_t n = params.size();
    const Param* p = params.begin();
    out.assign(n, Checked{});
    std::vector<bool> given(n, false), named(n, false);
    for (size_t k = 0; k < call.args.size(); ++k) {
        const ast::Arg& a = call.call->args[k];
        if (a.output) {
            ck.error(diag::E0302, a.loc, fmt::format("'{}' has no output '{}'", written(call), a.name));
            return false;
        }
        size_t idx = n;
        if (call.names[k].empty()) {
            // By its position in the call, also after named ones:
            // `AssertEquals(Expected := e, Actual := a, 'msg')` (decision 0204).
            idx = k;
            if (idx >= n) {
                ck.error(diag::E0301, call.loc, fmt::format("too many arguments for '{}' (it takes {})", written(call), n));
                return false;
            }
        } else {
            for (size_t j = 0; j < n; ++j)
                if (call.names[k] == sema::upper(p[j].name)) idx = j;
            if (idx == n) {
                ck.error(diag::E0302, a.loc, fmt::format("'{}' has no parameter '{}'", written(call), a.name));
                return false;
            }
        }
        if (given[idx]) {
            // Named twice: W0044 and the last value, as for a user POU (decision 0426).
            if (named[idx] && !call.names[k].empty()) {
                if (!sema::rebindNamedTwice(ck, call, a.loc, p[idx].name, out[idx], call.args[k], written(call))) return false;
                continue;
            }
            ck.error(diag::E0302, a.loc, fmt::format("parameter '{}' of '{}' given twice", p[idx].name, written(call)));
            return false;
        }
        given[idx] = true;
        named[idx] = !call.names[k].empty();
        out[idx] = call.args[k];
    }
    for (size_t j = 0; j < n; ++j)
        if (p[j].required && !given[j]) {
            ck.error(diag::E0301, call.loc, fmt::format("'{}' needs the input '{}'", written(call), p[j].name));
            return false;
        }
    return true;
}

Checked result(Checker& ck, exec::Expr* node, TK kind, const CallArgs& call) {
    node->type = ck.types().elementary(kind);
    Checked r;
    r.ok = true;
    r.loc = call.loc;
    r.type = node->type;
    r.node = node;
    r.hasCall = true;
    return r;
}

}  // namespace strun::testing::native_call
