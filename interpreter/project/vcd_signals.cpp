#include "interpreter/project/vcd_signals.h"

#include <algorithm>
#include <cctype>
#include <map>
#include <memory>
#include <optional>

#include "interpreter/project/variable_path.h"

namespace strun::project {

using sema::TK;

bool matchesPattern(std::string_view pattern, std::string_view text) {
    // Iterative glob with backtracking to the last '*': linear in practice.
    size_t p = 0, t = 0, star = std::string_view::npos, mark = 0;
    auto same = [](char a, char b) { return std::tolower(static_cast<unsigned char>(a)) == std::tolower(static_cast<unsigned char>(b)); };
    while (t < text.size()) {
        if (p < pattern.size() && pattern[p] == '*') {
            star = p++;
            mark = t;
        } else if (p < pattern.size() && same(pattern[p], text[t])) {
            ++p;
            ++t;
        } else if (star != std::string_view::npos) {
            p = star + 1;
            t = ++mark;
        } else {
            return false;
        }
    }
    while (p < pattern.size() && pattern[p] == '*') ++p;
    return p == pattern.size();
}

namespace {

// How a type is drawn; false for what is not recorded (strings, unless
// `text`: then STRINGs as text and enumerations by their value names).
bool encode(const sema::Type* t, rt::VcdSignal& s, bool text) {
    TK k = t->kind;
    s.size = t->size;
    if (text && k == TK::String) {
        s.kind = rt::VcdSignal::Kind::Text;
        return true;
    }
    if (text && k == TK::Enum) {
        s.kind = rt::VcdSignal::Kind::EnumName;
        s.isSigned = t->base && sema::isSignedInt(t->base->kind);
        for (const auto& e : t->enumerators) s.names.emplace_back(e.value, e.name);
        return true;
    }
    if (k == TK::Bool) {
        s.kind = rt::VcdSignal::Kind::Bit;
        return true;
    }
    if (k == TK::Real || k == TK::LReal) {
        s.kind = k == TK::Real ? rt::VcdSignal::Kind::Real32 : rt::VcdSignal::Kind::Real64;
        return true;
    }
    if (k == TK::String || k == TK::WString) return false;
    s.kind = rt::VcdSignal::Kind::Vector;
    if (sema::isTimeLike(k) || sema::isDateLike(k)) {
        // TIME as its nanoseconds (dates too: ns since 1970).
        s.width = 64;
        s.isSigned = k == TK::Time || t->size == 8;
        s.scale = sema::nanosPerUnit(k);
        return true;
    }
    if (k == TK::Enum) {
        s.width = int(t->size * 8);
        s.isSigned = t->base && sema::isSignedInt(t->base->kind);
        return true;
    }
    if (!(sema::isInteger(k) || sema::isBitString(k) || sema::isCharType(k))) return false;
    s.width = int(t->size * 8);
    s.isSigned = sema::isSignedInt(k);
    return true;
}

// `levels[3]` would read as a bit select in a VCD reference: `levels(3)`.
std::string leafName(std::string name) {
    for (char& c : name) {
        if (c == '[') c = '(';
        else if (c == ']') c = ')';
    }
    return name;
}

}  // namespace

std::vector<rt::VcdSignal> vcdSignals(const sema::ProgramModel& model, const std::vector<std::string>& patterns,
                                      std::vector<std::string>& unmatched, bool& truncated, bool text) {
    std::map<const sema::ProgramInstance*, int> taskOf;
    for (size_t i = 0; i < model.tasks.size(); ++i)
        for (const auto& call : model.tasks[i].calls)
            if (call.program && !taskOf.count(call.program)) taskOf[call.program] = int(i);
    std::vector<bool> used(patterns.size(), false);
    std::vector<rt::VcdSignal> signals;
    // The elements of one array (members of one instance) share one list of scope names.
    std::shared_ptr<const std::vector<std::string>> scopes;
    std::vector<std::string> scopesOf;  // what `scopes` was made from
    truncated = false;
    forEachElementary(model, [&](const ElementaryVar& v) {
        rt::VcdSignal s;
        if (!encode(v.ref.type, s, text)) return true;
        if (!patterns.empty()) {
            bool any = false;
            for (size_t i = 0; i < patterns.size(); ++i)
                if (matchesPattern(patterns[i], v.ref.path)) any = used[i] = true;
            if (!any) return true;
        }
        if (signals.size() >= kMaxVcdSignals) {
            truncated = true;
            return false;
        }
        if (!scopes || v.scopes != scopesOf) {
            scopesOf = v.scopes;
            auto names = std::make_shared<std::vector<std::string>>();
            for (const std::string& scope : v.scopes) names->push_back(leafName(scope));
            if (names->empty()) names->push_back("globals");
            scopes = std::move(names);
        }
        s.scopes = scopes;
        s.name = leafName(v.name);
        s.addr = v.ref.addr;
        s.bit = v.ref.bit;
        if (v.ref.program) {
            auto it = taskOf.find(v.ref.program);
            s.task = it == taskOf.end() ? -2 : it->second;  // -2: no task runs it, sampled never
        }
        signals.push_back(std::move(s));
        return true;
    });
    // The physical outputs (what the field last received, after the output
    // phases: it differs from %Q while output writing is inhibited), one byte
    // each, only when a pattern names them: `%QB*`, `physical_outputs.*`.
    const rt::ProcessImage& image = model.machine.image;
    const size_t extent = std::min(image.outputExtent, rt::ProcessImage::kSize);
    auto outputScopes = std::make_shared<std::vector<std::string>>(1, "physical_outputs");
    for (size_t byte = 0; byte < extent && !patterns.empty() && !truncated; ++byte) {
        const std::string leaf = "QB" + std::to_string(byte);
        bool any = false;
        for (size_t i = 0; i < patterns.size(); ++i)
            if (matchesPattern(patterns[i], "%" + leaf) || matchesPattern(patterns[i], "physical_outputs." + leaf)) any = used[i] = true;
        if (!any) continue;
        if (signals.size() >= kMaxVcdSignals) {
            truncated = true;
            break;
        }
        rt::VcdSignal s;
        s.kind = rt::VcdSignal::Kind::Vector;
        s.width = 8;
        s.scopes = outputScopes;
        s.name = leaf;
        s.addr = image.physicalOutputs.data() + byte;
        s.task = rt::VcdSignal::kAfterOutputPhase;
        signals.push_back(std::move(s));
    }
    for (size_t i = 0; i < patterns.size() && !truncated; ++i)  // a cut walk did not try every pattern
        if (!used[i]) unmatched.push_back(patterns[i]);
    return signals;
}

namespace {

// "task:X" -> "X" (any case of "task:"), else nullopt.
std::optional<std::string_view> taskPattern(std::string_view p) {
    if (p.size() < 5 || p[4] != ':') return std::nullopt;
    for (size_t k = 0; k < 4; ++k)
        if (std::tolower(static_cast<unsigned char>(p[k])) != "task"[k]) return std::nullopt;
    return p.substr(5);
}

}  // namespace

std::vector<bool> vcdTaskSelection(const std::vector<std::string>& taskNames, const std::vector<std::string>& patterns,
                                   std::vector<std::string>& variablePatterns, std::vector<std::string>& unmatched) {
    // Every task by default (the contract's timeline); `task:P` patterns choose
    // only those tasks, `!task:P` leaves those out.
    bool anyPositive = false;
    for (const std::string& p : patterns)
        if (taskPattern(p)) anyPositive = true;
    std::vector<bool> chosen(taskNames.size(), !anyPositive);
    for (const std::string& p : patterns) {
        const bool negative = !p.empty() && p[0] == '!';
        auto task = taskPattern(negative ? std::string_view(p).substr(1) : std::string_view(p));
        if (!task) {
            variablePatterns.push_back(p);
            continue;
        }
        bool any = false;
        for (size_t i = 0; i < taskNames.size(); ++i)
            if (matchesPattern(*task, taskNames[i])) {
                any = true;
                chosen[i] = !negative;
            }
        if (!any) unmatched.push_back(p);
    }
    return chosen;
}

}  // namespace strun::project
