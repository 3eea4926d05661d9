#include "interpreter/source/twincat_tasks.h"

#include <cctype>
#include <cstdint>
#include <string>

namespace strun::source {

namespace {

// A whole non-negative decimal number (TwinCAT writes them so), else false.
bool wholeNumber(const char* text, int64_t max, int64_t& out) {
    std::string s = text;
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.pop_back();
    size_t i = 0;
    while (i < s.size() && std::isspace(static_cast<unsigned char>(s[i]))) ++i;
    if (i == s.size()) return false;
    int64_t v = 0;
    for (; i < s.size(); ++i) {
        if (!std::isdigit(static_cast<unsigned char>(s[i]))) return false;
        v = v * 10 + (s[i] - '0');
        if (v > max) return false;
    }
    out = v;
    return true;
}

bool identifier(const std::string& s) {
    if (s.empty()) return false;
    for (size_t i = 0; i < s.size(); ++i) {
        unsigned char ch = static_cast<unsigned char>(s[i]);
        if (!(std::isalnum(ch) || ch == '_' || (ch == '.' && i > 0))) return false;
    }
    return !std::isdigit(static_cast<unsigned char>(s[0]));
}

}  // namespace

void convertTwinCatTask(XmlConversion& c, const pugi::xml_node& task) {
    auto written = [&](const pugi::xml_node& n, const std::string& st) {
        auto [line, col] = c.where(n);
        c.out.written(st, line, col);
    };
    const std::string name = task.attribute("Name").value();
    if (!identifier(name) || name.find('.') != std::string::npos) {
        c.error(task, "task object: the task's Name '" + name + "' is not an identifier");
        return;
    }
    std::string params;
    // <CycleTime> counts microseconds (TwinCAT's own comment in the file says so); 0 or none: freewheeling.
    if (pugi::xml_node cycle = task.child("CycleTime")) {
        int64_t us = 0;
        if (!wholeNumber(cycle.child_value(), 1000000000000, us))
            c.error(cycle, "task object '" + name + "': <CycleTime> must be a whole number of microseconds, not '" +
                               std::string(cycle.child_value()) + "'");
        else if (us > 0)
            params += "INTERVAL := T#" + std::to_string(us) + "us";
    }
    if (pugi::xml_node prio = task.child("Priority")) {
        int64_t p = 0;
        if (!wholeNumber(prio.child_value(), 1000000, p))
            c.error(prio, "task object '" + name + "': <Priority> must be a whole number, not '" + std::string(prio.child_value()) + "'");
        else
            params += (params.empty() ? "" : ", ") + std::string("PRIORITY := ") + std::to_string(p);
    }
    written(task, std::string("CONFIGURATION ") + kTwinCatTasksConfiguration);
    written(task, "RESOURCE " + name + "_Resource ON PLC");
    written(task, "TASK " + name + (params.empty() ? "" : "(" + params + ")") + ";");
    // TwinCAT names a program's instance after the program: MAIN.x reads it.
    for (pugi::xml_node call : task.children("PouCall")) {
        pugi::xml_node n = call.child("Name");
        const std::string pou = n ? n.child_value() : "";
        if (!identifier(pou)) {
            c.error(n ? n : call, "task object '" + name + "': <PouCall> must name a PROGRAM, not '" + pou + "'");
            continue;
        }
        std::string instance = pou.substr(pou.rfind('.') == std::string::npos ? 0 : pou.rfind('.') + 1);
        written(n, "PROGRAM " + instance + " WITH " + name + " : " + pou + ";");
    }
    written(task, "END_RESOURCE");
    written(task, "END_CONFIGURATION");
}

}  // namespace strun::source
