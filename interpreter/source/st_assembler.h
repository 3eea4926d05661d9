// Builds the ST text of a project file that is not ST (TwinCAT and PLCopen
// XML): pieces of ST copied from the XML keep their place, so every
// diagnostic points at the XML line and column (SourceFile::origins).
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "interpreter/source/source_set.h"

namespace strun::source {

// Line and column (1-based) of byte offsets of one text. Lines end as XML
// ends them (XML 1.0 section 2.11, which pugixml applies to the text it
// hands over): CR LF, a lone LF, or a lone CR (old Mac files, some exports).
class TextPositions {
public:
    explicit TextPositions(std::string_view text) {
        lineStarts_.push_back(0);
        for (size_t i = 0; i < text.size(); ++i)
            if (text[i] == '\n' || (text[i] == '\r' && (i + 1 == text.size() || text[i + 1] != '\n'))) lineStarts_.push_back(i + 1);
    }
    std::pair<int, int> at(std::ptrdiff_t offset) const {
        if (offset < 0) return {1, 1};
        size_t lo = 0, hi = lineStarts_.size();
        while (hi - lo > 1) {
            size_t mid = (lo + hi) / 2;
            if (lineStarts_[mid] <= static_cast<size_t>(offset)) lo = mid;
            else hi = mid;
        }
        return {static_cast<int>(lo) + 1, static_cast<int>(static_cast<size_t>(offset) - lineStarts_[lo]) + 1};
    }

private:
    std::vector<size_t> lineStarts_;
};

class StAssembler {
public:
    // ST copied from the original file; its first character is at (line, col).
    void verbatim(std::string_view st, int line, int col, const std::string& element = {}) {
        bool first = true;
        size_t start = 0;
        while (start <= st.size()) {
            size_t end = st.find('\n', start);
            std::string_view piece = st.substr(start, end == std::string_view::npos ? std::string_view::npos : end - start);
            text_.append(piece);
            text_.push_back('\n');
            origins_.push_back({line, first ? col - 1 : 0, -1, element});
            first = false;
            ++line;
            if (end == std::string_view::npos) break;
            start = end + 1;
        }
    }
    // A line strun writes itself; messages about it point at (line, col) of the element it stands for.
    void written(std::string_view st, int line, int col, const std::string& element = {}) {
        text_.append(st);
        text_.push_back('\n');
        origins_.push_back({line, 0, col, element});
    }
    std::string& text() { return text_; }
    std::vector<LineOrigin>& origins() { return origins_; }

private:
    std::string text_;
    std::vector<LineOrigin> origins_;
};

}  // namespace strun::source
