// Tc2_System's TwinCAT_SystemInfoVarList: TwinCAT generates `_TaskInfo :
// ARRAY[1..n] OF PlcTaskSystemInfo` with n the PLC project's task count, and
// `_AppInfo.TaskCnt = n`. The library declares ARRAY[1..1]; once the
// configuration has made strun's tasks (buildConfiguration), the list is given
// the real bound, before any body is checked, so UPPER_BOUND(_TaskInfo, 1)
// and index checks see it (decision 0305). The refresh each activation is
// interpreter/builtins/libraries/task_info.cpp.
#include <algorithm>
#include <string_view>

#include "interpreter/sema/checker.h"

namespace strun::sema {

void Checker::sizeTaskInfoToTasks() {
    VarSym* list = nullptr;
    VarSym* app = nullptr;
    static constexpr std::string_view kList = "TWINCAT_SYSTEMINFOVARLIST";
    for (const auto& g : model_.globalStore) {
        // A size test first: this runs for every project, most have no such list.
        if (g->listName.size() != kList.size() || !g->decl || !libraryFiles_.count(g->decl->loc.file) || upper(g->listName) != kList)
            continue;
        const std::string key = upper(g->name);
        if (key == "_TASKINFO") list = g.get();
        else if (key == "_APPINFO") app = g.get();
    }
    const int64_t count = std::max<int64_t>(1, static_cast<int64_t>(model_.tasks.size()));
    if (list && list->type && list->type->kind == TK::Array && list->type->elem && list->type->dims.size() == 1 &&
        list->type->dims[0].count() != count) {
        const Type* sized = types().array(list->type->elem, {ArrayDim{1, count}}, false);
        uint8_t* storage = model_.allocate(sized->size);
        writeDefault(storage, sized);
        list->type = sized;
        list->abs = storage;
        model_.largestType = std::max(model_.largestType, sized->size);
    }
    if (app && app->abs && app->type)
        for (const Field& f : app->type->fields)
            if (upper(f.name) == "TASKCNT" && f.type && f.type->size == 4) {
                const uint32_t n = static_cast<uint32_t>(model_.tasks.size());
                std::copy_n(reinterpret_cast<const uint8_t*>(&n), 4, app->abs + f.offset);
            }
}

}  // namespace strun::sema
