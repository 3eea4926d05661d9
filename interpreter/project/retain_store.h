// RETAIN and PERSISTENT variables kept in a file across runs (--retain FILE).
//
// The file records, for every retained value, its path in the project
// ("Main.fb.count", "gRecipe.steps[2]"), its type and size, and its bytes; a
// checksum closes it. A warm start restores what still matches by path,
// type and size and warns about the rest, so a changed program never
// misreads bytes. Saves are atomic (temporary file, fsync, rename): a kill
// at any moment leaves the previous or the new complete file.
// Format and choices: docs/decisions/0130-retain-file.md.
#pragma once

#include <chrono>
#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

#include "interpreter/sema/program_model.h"

namespace strun::project {

class RetainStore {
public:
    // Collects the retained storage of `model` (globals, program and FB instance variables).
    RetainStore(sema::ProgramModel& model, std::string path, std::ostream& warnings);
    // Warm start: restores from the file when it exists (a missing file is a cold start).
    void restore();
    // Writes the file atomically; false (with a warning) when it cannot.
    bool save();
    // Saves when `every` has passed since the last save (real time). Called between activations.
    void saveIfDue() {
        if (every_.count() <= 0) return;
        auto now = std::chrono::steady_clock::now();
        if (now - lastSave_ >= every_) {
            lastSave_ = now;
            save();
        }
    }
    void setInterval(std::chrono::nanoseconds every) { every_ = every; lastSave_ = std::chrono::steady_clock::now(); }
    size_t valueCount() const { return values_.size(); }

    static constexpr size_t kMaxRetainedValues = 1000000;

private:
    struct Value {
        std::string path;
        std::string tag;  // type name and size: what must match to restore
        uint8_t* addr;
        uint32_t size;
    };
    void collect(const std::string& path, const sema::Type* t, uint8_t* addr, bool retained, int depth);
    std::string serialize() const;
    std::vector<Value> values_;
    std::string path_;
    std::ostream& warnings_;
    std::chrono::nanoseconds every_{0};
    std::chrono::steady_clock::time_point lastSave_{};
    bool truncated_ = false;
};

}  // namespace strun::project
