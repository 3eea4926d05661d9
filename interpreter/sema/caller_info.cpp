// {CallerFilePath} and {CallerLineNumber} (SIMATIC AX, decision 0363): an
// input marked with one of these pragmas that a call leaves out receives the
// path of the file the call is written in, or its line. AxUnit's assertions
// and a project's own assertion functions take them to say where a failed
// check is written (`axunit_Fail(msg, file, line)`). The values are
// constants of the call site, bound like any other argument.
#include <fmt/format.h>

#include "interpreter/sema/checker.h"
#include "interpreter/sema/node_factory.h"
#include "stdlib/text_encoding.h"

namespace strun::sema {

CallerInfo callerInfoOf(const VarSym* p) {
    if (!p || !p->decl || p->section != ast::VarSection::Input) return CallerInfo::None;
    for (const ast::Pragma& pr : p->decl->pragmas) {
        const std::string t = upper(pr.text);
        if (t == "CALLERFILEPATH") return CallerInfo::FilePath;
        if (t == "CALLERLINENUMBER") return CallerInfo::LineNumber;
    }
    return CallerInfo::None;
}

void Checker::bindCallerInfo(const PouInfo* fn, const std::set<VarSym*>& connected, const ast::Loc& loc, std::vector<exec::Stmt*>& inputs) {
    for (VarSym* p : fn->params) {
        const CallerInfo what = callerInfoOf(p);
        if (what == CallerInfo::None || connected.count(p)) continue;
        Checked value;
        if (what == CallerInfo::LineNumber) {
            value = constInt(loc.line, types().elementary(TK::DInt), loc);
            value.untypedInt = true;
        } else {
            const auto& paths = compileOptions().sourcePaths;
            const std::string path = loc.file >= 0 && static_cast<size_t>(loc.file) < paths.size() ? paths[static_cast<size_t>(loc.file)] : "";
            const bool wide = p->type && p->type->kind == TK::WString;
            std::vector<uint8_t> bytes;
            size_t len = path.size();
            if (wide) {
                std::u16string w = stdlib::stringToWString(path);
                if (auto u = stdlib::utf8ToUtf16(path); u.ok()) w = u.value();
                for (char16_t c : w) {
                    bytes.push_back(static_cast<uint8_t>(c & 0xFF));
                    bytes.push_back(static_cast<uint8_t>(c >> 8));
                }
                len = w.size();
                bytes.push_back(0);
                bytes.push_back(0);
            } else {
                bytes.assign(path.begin(), path.end());
                bytes.push_back(0);
            }
            value = constantString(std::move(bytes), len, wide, loc);
        }
        if (!value.ok) continue;
        Checked cv = coerce(value, p->type, loc, fmt::format("argument '{}'", p->name).c_str());
        if (!cv.ok) continue;
        exec::Expr* place = makeByRep<exec::PendingVar>(pool(), isAggregate(p->type) ? Rep::Void : repOf(p->type), p->offset);
        inputs.push_back(storeTo(place, p->type, cv.node));
    }
}

}  // namespace strun::sema
