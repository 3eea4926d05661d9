// The --dump JSON of the contract: final values of globals and program
// instances, encoded by type (shared/contract.md, "VALUE encodings").
#pragma once

#include <nlohmann/json.hpp>

#include "interpreter/sema/program_model.h"

namespace strun::project {

nlohmann::ordered_json valueToJson(const sema::Type* type, const uint8_t* p);
// Appends a member whose key is known to be new (ordered_json's operator[]
// searches linearly: quadratic for 100 000 members; this is O(1)).
void appendMember(nlohmann::ordered_json& obj, const std::string& key, nlohmann::ordered_json value);
nlohmann::ordered_json globalsJson(const sema::ProgramModel& model);
nlohmann::ordered_json programsJson(const sema::ProgramModel& model);
// The physical output image, what the field last received (after each task's
// output phase): {"%QB0": 5, ...}, the bytes that are not 0 in address order.
// It differs from the %Q variables while output writing is inhibited (M340
// %SW9) or not yet done.
nlohmann::ordered_json physicalOutputsJson(const sema::ProgramModel& model);

}  // namespace strun::project
