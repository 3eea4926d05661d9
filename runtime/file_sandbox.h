// The host directory the PLC's file blocks (Tc2_System FB_File*, decision
// 0221) work in, and the open files. A path from the PLC program is taken
// relative to the sandbox root: an absolute path (`/x`, `C:\x`, `\\host\x`),
// a `..` component or a symbolic link anywhere on the way is refused, so no
// path can leave the directory. Windows separators `\` count as `/`.
// Every operation completes at once (host files are local); the blocks
// around them report busy for one call as TwinCAT's do.
#pragma once

#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>
#include <vector>

namespace strun::rt {

// ADS error codes the file blocks answer with (nErrId), as TwinCAT's.
namespace file_error {
constexpr uint32_t kNone = 0;
constexpr uint32_t kDeviceError = 0x700;     // 1792 ADSERR_DEVICE_ERROR: another host error
constexpr uint32_t kInvalidParam = 0x70B;    // 1803 ADSERR_DEVICE_INVALIDPARM: bad mode, bad handle, empty path
constexpr uint32_t kNotFound = 0x70C;        // 1804 ADSERR_DEVICE_NOTFOUND: no such file or directory
constexpr uint32_t kExists = 0x70F;          // 1807 ADSERR_DEVICE_EXISTS: already exists / directory not empty
constexpr uint32_t kNoMoreHandles = 0x716;   // 1814 ADSERR_DEVICE_NOMOREHDLS: too many open files
constexpr uint32_t kAccessDenied = 0x723;    // 1827 ADSERR_DEVICE_ACCESSDENIED: path leaves the sandbox, or permission
}  // namespace file_error

class FileSandbox {
public:
    // The directory (created when missing). "" = a new temporary directory on first use.
    void setRoot(std::string dir) { root_ = std::move(dir); }
    const std::string& root();
    ~FileSandbox();
    // At the end of a run: closes the files the program left open and removes
    // the directory when it was a temporary one strun made (the process ends
    // with _Exit, so this is not left to a destructor).
    void finish();

    // FOPEN_MODE* flags (READ 1, WRITE 2, APPEND 4, PLUS 8, BINARY 16, TEXT 32).
    // Returns a handle >= 1, or 0 and sets `err`.
    uint32_t open(std::string_view path, uint32_t mode, uint32_t& err);
    uint32_t close(uint32_t handle);
    // Bytes read (fewer than asked at the end of the file: eof set).
    uint32_t read(uint32_t handle, void* buf, uint32_t len, uint32_t& got, bool& eof);
    uint32_t write(uint32_t handle, const void* buf, uint32_t len, uint32_t& put);
    // One line with its '\n' (at most maxLen bytes); eof when nothing was left.
    uint32_t gets(uint32_t handle, std::string& line, uint32_t maxLen, bool& eof);
    uint32_t seek(uint32_t handle, int64_t pos, int origin);
    uint32_t tell(uint32_t handle, int64_t& pos);
    uint32_t remove(std::string_view path);
    uint32_t rename(std::string_view from, std::string_view to);
    uint32_t makeDir(std::string_view path);
    uint32_t removeDir(std::string_view path);

    // Directory listings (CODESYS CAA File DirOpen/DirList/DirClose): the
    // entries of the directory as they are when it is opened, without "."
    // and "..", sorted by name. "" and "." name the sandbox root itself.
    struct DirEntry {
        std::string name;
        uint64_t size = 0;       // bytes of a regular file, else 0
        bool directory = false;
        int64_t modified = 0;    // seconds since 1970 (UTC)
    };
    uint32_t openDir(std::string_view path, uint32_t& err);  // handle >= 1, or 0 and err
    // The next entry; false (and err 0) when none is left.
    bool nextEntry(uint32_t handle, DirEntry& entry, uint32_t& err);
    // The entry nextEntry gave last (for the natives that read its parts).
    const DirEntry* lastEntry(uint32_t handle) const;
    uint32_t closeDir(uint32_t handle);

    static constexpr size_t kMaxOpen = 64;

private:
    // The directory holding the path's last component (an open fd, walked
    // from the root without following links) and that component.
    int openParent(std::string_view path, std::string& leaf, uint32_t& err);
    std::FILE* file(uint32_t handle);
    std::string root_;
    bool created_ = false;
    bool temporary_ = false;
    std::vector<std::FILE*> files_;
    struct Listing {
        bool open = false;
        std::vector<DirEntry> entries;
        size_t next = 0;
    };
    std::vector<Listing> dirs_;
};

// The process's sandbox (the CLI sets its root from --files).
FileSandbox& fileSandbox();

}  // namespace strun::rt
