// Tc2_System's TwinCAT_SystemInfoVarList._TaskInfo[]: filled from strun's
// own tasks at the start of every activation, when (and only when) the
// project uses the list (decision 0220).
#pragma once

#include "interpreter/sema/program_model.h"

namespace strun::stdlib {

// The statement that refreshes _TaskInfo[], or null when the project does not
// declare it (the library's file was not selected).
exec::Stmt* makeTaskInfoRefresh(sema::ProgramModel& model);

}  // namespace strun::stdlib
