// Variables named from outside the program (--set, --stimulus, --watch,
// --vcd): a path as a user writes it, resolved against the checked model
// to storage and type once, before the run.
//
// Paths (case-insensitive): `Instance.var`, `Instance.fb.member`,
// `Instance.arr[2]`, `Instance.m[1,2]`, `Instance.s.arr[3].x`, a global's
// name `gX`, or `List.gX` (any prefix that is not a program instance before
// a global's name: a global variable list's name).
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "interpreter/sema/program_model.h"

namespace strun::project {

struct VariableRef {
    std::string path;  // as declared: "Main.valve.cmd", "Main.levels[3]", "gCount"
    const sema::Type* type = nullptr;
    uint8_t* addr = nullptr;
    int bit = -1;            // BOOL at a bit address (AT %IX0.3)
    bool constant = false;   // CONSTANT: not writable from outside
    const sema::ProgramInstance* program = nullptr;  // owning instance; nullptr for a global
};

// nullopt with `error` ("no variable 'x' in program instance 'Main'") when
// the path names nothing, or names a pointer/reference/interface.
std::optional<VariableRef> resolveVariablePath(const sema::ProgramModel& model, std::string_view path, std::string& error);

// An elementary variable for recording: `scopes` are the enclosing
// instance/struct names ("Main", "valve"), `name` the leaf ("cmd", "levels[3]").
// `scopes` is the walk's own, valid during the visit only (never copied per element).
struct ElementaryVar {
    VariableRef ref;
    const std::vector<std::string>& scopes;
    std::string name;
};
// Every elementary variable of every program instance (VAR_TEMP and
// in-out references excepted) and every global, in declaration order;
// struct and FB members and array elements expanded. The walk ends early
// when `visit` returns false.
void forEachElementary(const sema::ProgramModel& model, const std::function<bool(const ElementaryVar&)>& visit);

}  // namespace strun::project
