// One fuzz iteration, independent of libFuzzer: compile a project against the
// standard library parsed once, run it for a bounded PLC time on the virtual
// clock, and dump its state. Three kinds of input: ST text, an XML project
// file (PLCopen TC6 or a TwinCAT object), and the bytes of a retain file
// restored into a fixed program with retained variables of every kind.
// Shared by the libFuzzer targets and their unit test.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>

#include "interpreter/project/compile.h"

namespace strun::fuzz {

class Session {
public:
    Session();
    ~Session();
    // Each returns the --dump JSON text of the run ("" when the input did not compile).
    std::string runOnce(const uint8_t* data, size_t size);     // ST source
    std::string runXml(const uint8_t* data, size_t size);      // PLCopen XML or TwinCAT object
    std::string runRetain(const uint8_t* data, size_t size);   // retain file of retainProgram()

    // The program whose retain files runRetain reads, and a valid retain file of
    // it (after one run that changed every retained value): the seed of that
    // target. A file whose last line is "END FIX" gets its checksum line
    // computed before it is read, so that mutated values reach the value
    // checks; `checksumToFix` gives the seed in that form.
    static const char* retainProgram();
    std::string validRetainFile(bool checksumToFix = false);

    static constexpr size_t kMaxInputBytes = 64 * 1024;
    static constexpr int64_t kPlcTimeNanos = 5'000'000;  // 5 ms of PLC time = 5 000 statements at 1 us

private:
    // `retained`: restore from (and save to) the scratch retain file, first
    // written with `retainBytes` unless null (then absent: a cold start).
    std::string compileAndRun(SourceSet& sources, const std::vector<int>& files, bool retained, const std::string* retainBytes);
    CompileLog libraryLog_;
    std::unique_ptr<project::ParsedLibrary> library_;
    std::string retainPath_;  // this process's scratch retain file
};

}  // namespace strun::fuzz
