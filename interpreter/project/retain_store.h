// RETAIN and PERSISTENT variables kept in a file across runs (--retain FILE).
//
// The file records, for every retained value, its path in the project
// ("Main.fb.count", "gRecipe.steps[2]"), its type and size, and its bytes; a
// checksum closes it. A warm start restores what still matches by path,
// type and size and holds a valid value of its type, and warns about the
// rest, so a changed program or a crafted file never misreads bytes. Saves
// are atomic (temporary file, fsync, rename): a kill at any moment leaves
// the previous or the new complete file. The file is read and written in
// pieces (never whole in memory), and a file larger than this project's
// retained variables can explain is not read (sizeLimit()).
// Format and choices: docs/decisions/0130-retain-file.md, 0250, 0251.
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
    // Also keeps these system words (%SWn of the process image) across a
    // warm start: the M340's maximum and minimum cycle times (seed 002,
    // decision 0296). Before start().
    void keepSystemWords(sema::ProgramModel& model, const std::vector<int>& words);
    // Before the run: FILE must be a regular file or not exist, must not be
    // one of `inputs`, and when it exists and is not empty it must be a
    // retain file unless `cold` (strun overwrites only its own files).
    // Then, unless `cold`, the warm start: restores from the file (a missing
    // or damaged file is a cold start, with a warning for a damaged one).
    // False with `error` (a usage error, exit 2) when FILE may not be used.
    bool start(bool cold, const std::vector<std::string>& inputs, std::string& error);
    // Writes the file atomically; false (with a warning unless `quiet`) when it cannot.
    bool save(bool quiet = false);
    // The largest retain file this project reads: twice the size of the
    // file its retained variables make, plus 1 MiB (room for values of an
    // earlier version of the program, which are dropped with a warning).
    uint64_t sizeLimit() const;
    // Saves when `every` has passed since the last save (real time). Called between activations.
    void saveIfDue() {
        if (every_.count() <= 0) return;
        auto now = std::chrono::steady_clock::now();
        if (now - lastSave_ >= every_) {
            lastSave_ = now;
            // A failing periodic save (a full disk) is reported once, not every interval, until one succeeds.
            const bool saved = save(failing_);
            failing_ = !saved;
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
        const sema::Type* type;
    };
    void collect(const std::string& path, const sema::Type* t, uint8_t* addr, bool retained, int depth);
    void restore(int fd);
    bool writeTo(int fd) const;
    std::vector<Value> values_;
    std::string path_;
    std::ostream& warnings_;
    std::chrono::nanoseconds every_{0};
    std::chrono::steady_clock::time_point lastSave_{};
    bool truncated_ = false;
    bool failing_ = false;  // the last periodic save failed (and said so)
    std::string target_;  // the file renamed over: path_, or where a symbolic link at path_ leads
};

}  // namespace strun::project
