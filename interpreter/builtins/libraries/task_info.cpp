#include "interpreter/builtins/libraries/task_info.h"

#include <algorithm>
#include <cstring>

#include "interpreter/sema/types.h"
#include "runtime/machine.h"

namespace strun::stdlib {

namespace {

// Where each member of PlcTaskSystemInfo lies in one element (-1: absent).
struct Layout {
    int cycleTime = -1, priority = -1, adsPort = -1, cycleCount = -1, dcTaskTime = -1, lastExecTime = -1, firstCycle = -1,
        cycleTimeExceeded = -1, taskName = -1;
    uint32_t nameMax = 0;
};

struct TaskInfoRefresh final : exec::Stmt {
    uint8_t* base;
    uint32_t stride;
    int64_t lo, count;
    Layout at;
    TaskInfoRefresh(uint8_t* b, uint32_t s, int64_t l, int64_t n, Layout a) : base(b), stride(s), lo(l), count(n), at(a) {}

    template <typename T>
    static void put(uint8_t* element, int offset, T value) {
        if (offset >= 0) std::memcpy(element + offset, &value, sizeof value);
    }

    exec::Flow exec(exec::Ctx& c) override {
        rt::AttentionHandler* h = c.m->handler;
        if (!h) return exec::Flow::Next;
        const int current = h->currentTaskIndex();
        rt::AttentionHandler::TaskInfo info;
        for (int64_t i = 0; i < count; ++i) {
            const int index = static_cast<int>(lo + i);
            if (!h->taskInfo(index, info)) continue;
            uint8_t* e = base + static_cast<size_t>(i) * stride;
            put<uint32_t>(e, at.cycleTime, static_cast<uint32_t>(info.interval / 100));
            put<uint16_t>(e, at.priority, static_cast<uint16_t>(info.priority));
            put<uint16_t>(e, at.adsPort, 851);
            put<uint32_t>(e, at.cycleCount, static_cast<uint32_t>(info.started));
            put<uint32_t>(e, at.lastExecTime, static_cast<uint32_t>(info.lastExec / 100));
            put<uint8_t>(e, at.firstCycle, info.started == 1 ? 1 : 0);
            put<uint8_t>(e, at.cycleTimeExceeded, info.overrun ? 1 : 0);
            if (index == current) {
                // DC time of the activation's start: ns since 2000 (0 before 2000).
                const int64_t dc = h->taskStartCalendarNanos() - 946'684'800LL * 1'000'000'000LL;
                put<int64_t>(e, at.dcTaskTime, dc > 0 ? dc : 0);
            }
            if (at.taskName >= 0) {
                const size_t n = std::min<size_t>(info.name.size(), at.nameMax);
                std::memcpy(e + at.taskName, info.name.data(), n);
                e[at.taskName + static_cast<int>(n)] = 0;
            }
        }
        return exec::Flow::Next;
    }
};

}  // namespace

exec::Stmt* makeTaskInfoRefresh(sema::ProgramModel& model) {
    const sema::VarSym* list = nullptr;
    // The library's globals are not in model.globals (not the project's state).
    for (const auto& g : model.globalStore)
        if (g->name.size() == 9 && sema::upper(g->name) == "_TASKINFO") list = g.get();
    if (!list || !list->abs || !list->type || list->type->kind != sema::TK::Array || !list->type->elem ||
        list->type->dims.size() != 1)
        return nullptr;
    const sema::Type* element = list->type->elem;
    Layout at;
    for (const sema::Field& f : element->fields) {
        const std::string name = sema::upper(f.name);
        const int offset = static_cast<int>(f.offset);
        if (name == "CYCLETIME") at.cycleTime = offset;
        else if (name == "PRIORITY") at.priority = offset;
        else if (name == "ADSPORT") at.adsPort = offset;
        else if (name == "CYCLECOUNT") at.cycleCount = offset;
        else if (name == "DCTASKTIME") at.dcTaskTime = offset;
        else if (name == "LASTEXECTIME") at.lastExecTime = offset;
        else if (name == "FIRSTCYCLE") at.firstCycle = offset;
        else if (name == "CYCLETIMEEXCEEDED") at.cycleTimeExceeded = offset;
        else if (name == "TASKNAME" && f.type && f.type->kind == sema::TK::String) {
            at.taskName = offset;
            at.nameMax = f.type->maxLen;
        }
    }
    return model.pool.make<TaskInfoRefresh>(list->abs, element->size, list->type->dims[0].lo, list->type->dims[0].count(), at);
}

}  // namespace strun::stdlib
