// Translated ST put into an ST file (st_splice.h).
#include "interpreter/source/st_splice.h"

#include <algorithm>

#include "interpreter/source/st_assembler.h"

namespace strun::source {

void spliceSt(const std::string& src, const std::vector<std::pair<size_t, size_t>>& blanked, std::vector<StSplice> splices,
              Converted& result) {
    std::string text = src;
    for (auto [from, to] : blanked)
        for (size_t i = from; i < to && i < text.size(); ++i)
            if (text[i] != '\n' && text[i] != '\r') text[i] = ' ';
    std::stable_sort(splices.begin(), splices.end(), [](const StSplice& a, const StSplice& b) { return a.at < b.at; });
    StAssembler out;
    TextPositions pos(src);
    auto emit = [&](const std::vector<plcopen::StLine>& lines) {
        for (const plcopen::StLine& l : lines) {
            if (l.verbatim) out.verbatim(l.text, l.line, l.col, l.element);
            else out.written(l.text, l.line, l.col, l.element);
        }
    };
    size_t done = 0;
    for (const StSplice& s : splices) {
        if (s.at > done) {
            auto [line, col] = pos.at(static_cast<std::ptrdiff_t>(done));
            out.verbatim(std::string_view(text).substr(done, s.at - done), line, col);
            done = s.at;
        }
        if (!s.declarations.empty()) {
            const plcopen::StLine& d = s.declarations.front();
            out.written("VAR", d.line, d.col);
            emit(s.declarations);
            out.written("END_VAR", d.line, d.col);
        }
        emit(s.body);
    }
    auto [line, col] = pos.at(static_cast<std::ptrdiff_t>(done));
    out.verbatim(std::string_view(text).substr(done), line, col);
    result.text = std::move(out.text());
    result.origins = std::move(out.origins());
}

}  // namespace strun::source
