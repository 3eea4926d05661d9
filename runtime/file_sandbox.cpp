#include "runtime/file_sandbox.h"

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>

#include <dirent.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace strun::rt {

namespace {

uint32_t fromErrno(int e) {
    switch (e) {
        case ENOENT: return file_error::kNotFound;
        case EEXIST:
        case ENOTEMPTY: return file_error::kExists;
        case ELOOP:
        case EACCES:
        case EPERM:
        case EXDEV: return file_error::kAccessDenied;
        case ENOTDIR:
        case EISDIR:
        case EINVAL: return file_error::kInvalidParam;
        case EMFILE:
        case ENFILE: return file_error::kNoMoreHandles;
        default: return file_error::kDeviceError;
    }
}

// The path's components; false when it is absolute or climbs with `..`.
bool components(std::string_view path, std::vector<std::string>& out) {
    std::string p(path);
    for (char& c : p)
        if (c == '\\') c = '/';
    if (p.empty() || p[0] == '/') return false;
    if (p.size() >= 2 && p[1] == ':') return false;  // C:\...
    size_t at = 0;
    while (at <= p.size()) {
        size_t slash = p.find('/', at);
        if (slash == std::string::npos) slash = p.size();
        std::string part = p.substr(at, slash - at);
        at = slash + 1;
        if (part.empty() || part == ".") continue;
        if (part == "..") return false;
        out.push_back(part);
    }
    return !out.empty();
}

}  // namespace

FileSandbox& fileSandbox() {
    static FileSandbox sandbox;
    return sandbox;
}

FileSandbox::~FileSandbox() {
    for (std::FILE* f : files_)
        if (f) std::fclose(f);
}

void FileSandbox::finish() {
    for (std::FILE*& f : files_)
        if (f) {
            std::fclose(f);
            f = nullptr;
        }
    dirs_.clear();
    if (temporary_ && !root_.empty()) {
        std::error_code ignored;
        std::filesystem::remove_all(root_, ignored);
        root_.clear();
        created_ = temporary_ = false;
    }
}

const std::string& FileSandbox::root() {
    if (root_.empty()) {
        const char* tmp = std::getenv("TMPDIR");
        std::string templ = std::string(tmp && *tmp ? tmp : "/tmp") + "/strun-files-XXXXXX";
        std::vector<char> buf(templ.begin(), templ.end());
        buf.push_back(0);
        if (::mkdtemp(buf.data())) root_ = buf.data();
        created_ = true;
        temporary_ = true;
    } else if (!created_) {
        ::mkdir(root_.c_str(), 0755);  // an existing directory stays as it is
        created_ = true;
    }
    return root_;
}

int FileSandbox::openParent(std::string_view path, std::string& leaf, uint32_t& err) {
    std::vector<std::string> parts;
    if (!components(path, parts)) {
        err = path.empty() ? file_error::kInvalidParam : file_error::kAccessDenied;
        return -1;
    }
    int fd = ::open(root().c_str(), O_DIRECTORY | O_RDONLY | O_CLOEXEC);
    if (fd < 0) {
        err = fromErrno(errno);
        return -1;
    }
    for (size_t i = 0; i + 1 < parts.size(); ++i) {
        int next = ::openat(fd, parts[i].c_str(), O_DIRECTORY | O_RDONLY | O_NOFOLLOW | O_CLOEXEC);
        int e = errno;
        // A link on the way (O_NOFOLLOW|O_DIRECTORY answers ENOTDIR or ELOOP): refused as leaving the sandbox.
        struct stat st {};
        const bool link = next < 0 && ::fstatat(fd, parts[i].c_str(), &st, AT_SYMLINK_NOFOLLOW) == 0 && S_ISLNK(st.st_mode);
        ::close(fd);
        if (next < 0) {
            err = link ? file_error::kAccessDenied : fromErrno(e);
            return -1;
        }
        fd = next;
    }
    leaf = parts.back();
    return fd;
}

std::FILE* FileSandbox::file(uint32_t handle) {
    if (handle == 0 || handle > files_.size()) return nullptr;
    return files_[handle - 1];
}

uint32_t FileSandbox::open(std::string_view path, uint32_t mode, uint32_t& err) {
    err = 0;
    const bool read = mode & 1, write = mode & 2, append = mode & 4, plus = mode & 8;
    int flags;
    const char* fmode;
    if (append) {
        flags = (plus ? O_RDWR : O_WRONLY) | O_CREAT | O_APPEND;
        fmode = plus ? "a+" : "a";
    } else if (write) {
        flags = (plus ? O_RDWR : O_WRONLY) | O_CREAT | O_TRUNC;
        fmode = plus ? "w+" : "w";
    } else if (read) {
        flags = plus ? O_RDWR : O_RDONLY;
        fmode = plus ? "r+" : "r";
    } else {
        err = file_error::kInvalidParam;
        return 0;
    }
    size_t slot = 0;
    while (slot < files_.size() && files_[slot]) ++slot;
    if (slot >= kMaxOpen) {
        err = file_error::kNoMoreHandles;
        return 0;
    }
    std::string leaf;
    int dir = openParent(path, leaf, err);
    if (dir < 0) return 0;
    int fd = ::openat(dir, leaf.c_str(), flags | O_NOFOLLOW | O_CLOEXEC, 0644);
    int e = errno;
    ::close(dir);
    if (fd < 0) {
        err = fromErrno(e);
        return 0;
    }
    struct stat st {};
    if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
        ::close(fd);
        err = file_error::kInvalidParam;
        return 0;
    }
    std::FILE* f = ::fdopen(fd, fmode);
    if (!f) {
        ::close(fd);
        err = file_error::kDeviceError;
        return 0;
    }
    if (slot == files_.size()) files_.push_back(f);
    else files_[slot] = f;
    return static_cast<uint32_t>(slot + 1);
}

uint32_t FileSandbox::close(uint32_t handle) {
    std::FILE* f = file(handle);
    if (!f) return file_error::kInvalidParam;
    files_[handle - 1] = nullptr;
    return std::fclose(f) == 0 ? 0 : file_error::kDeviceError;
}

uint32_t FileSandbox::read(uint32_t handle, void* buf, uint32_t len, uint32_t& got, bool& eof) {
    got = 0;
    eof = false;
    std::FILE* f = file(handle);
    if (!f) return file_error::kInvalidParam;
    got = static_cast<uint32_t>(std::fread(buf, 1, len, f));
    if (std::ferror(f)) {
        std::clearerr(f);
        return file_error::kDeviceError;
    }
    eof = got < len;
    return 0;
}

uint32_t FileSandbox::write(uint32_t handle, const void* buf, uint32_t len, uint32_t& put) {
    put = 0;
    std::FILE* f = file(handle);
    if (!f) return file_error::kInvalidParam;
    put = static_cast<uint32_t>(std::fwrite(buf, 1, len, f));
    std::fflush(f);
    if (put < len) {
        std::clearerr(f);
        return file_error::kDeviceError;
    }
    return 0;
}

uint32_t FileSandbox::gets(uint32_t handle, std::string& line, uint32_t maxLen, bool& eof) {
    line.clear();
    eof = false;
    std::FILE* f = file(handle);
    if (!f) return file_error::kInvalidParam;
    int c = 0;
    while (line.size() < maxLen && (c = std::fgetc(f)) != EOF) {
        line.push_back(static_cast<char>(c));
        if (c == '\n') break;
    }
    if (line.empty() && c == EOF) eof = true;
    return 0;
}

uint32_t FileSandbox::seek(uint32_t handle, int64_t pos, int origin) {
    std::FILE* f = file(handle);
    if (!f) return file_error::kInvalidParam;
    const int whence = origin == 1 ? SEEK_CUR : origin == 2 ? SEEK_END : SEEK_SET;
    return std::fseek(f, static_cast<long>(pos), whence) == 0 ? 0 : file_error::kInvalidParam;
}

uint32_t FileSandbox::tell(uint32_t handle, int64_t& pos) {
    std::FILE* f = file(handle);
    if (!f) return file_error::kInvalidParam;
    pos = std::ftell(f);
    return pos < 0 ? file_error::kDeviceError : 0;
}

uint32_t FileSandbox::remove(std::string_view path) {
    uint32_t err = 0;
    std::string leaf;
    int dir = openParent(path, leaf, err);
    if (dir < 0) return err;
    int r = ::unlinkat(dir, leaf.c_str(), 0);  // a link itself is removed, never its target
    int e = errno;
    ::close(dir);
    return r == 0 ? 0 : fromErrno(e);
}

uint32_t FileSandbox::rename(std::string_view from, std::string_view to) {
    uint32_t err = 0;
    std::string leafFrom, leafTo;
    int dirFrom = openParent(from, leafFrom, err);
    if (dirFrom < 0) return err;
    int dirTo = openParent(to, leafTo, err);
    if (dirTo < 0) {
        ::close(dirFrom);
        return err;
    }
    int r = ::renameat(dirFrom, leafFrom.c_str(), dirTo, leafTo.c_str());
    int e = errno;
    ::close(dirFrom);
    ::close(dirTo);
    return r == 0 ? 0 : fromErrno(e);
}

uint32_t FileSandbox::makeDir(std::string_view path) {
    uint32_t err = 0;
    std::string leaf;
    int dir = openParent(path, leaf, err);
    if (dir < 0) return err;
    int r = ::mkdirat(dir, leaf.c_str(), 0755);
    int e = errno;
    ::close(dir);
    return r == 0 ? 0 : fromErrno(e);
}

uint32_t FileSandbox::removeDir(std::string_view path) {
    uint32_t err = 0;
    std::string leaf;
    int dir = openParent(path, leaf, err);
    if (dir < 0) return err;
    int r = ::unlinkat(dir, leaf.c_str(), AT_REMOVEDIR);
    int e = errno;
    ::close(dir);
    return r == 0 ? 0 : fromErrno(e);
}

// ---------------------------------------------------------------- directory listings

uint32_t FileSandbox::openDir(std::string_view path, uint32_t& err) {
    err = 0;
    size_t slot = 0;
    while (slot < dirs_.size() && dirs_[slot].open) ++slot;
    if (slot >= kMaxOpen) {
        err = file_error::kNoMoreHandles;
        return 0;
    }
    std::string p(path);
    for (char& c : p)
        if (c == '\\') c = '/';
    while (p.size() > 1 && p.back() == '/') p.pop_back();
    int fd = -1;
    if (p.empty() || p == ".") {
        fd = ::open(root().c_str(), O_DIRECTORY | O_RDONLY | O_CLOEXEC);
        if (fd < 0) err = fromErrno(errno);
    } else {
        std::string leaf;
        int parent = openParent(p, leaf, err);
        if (parent < 0) return 0;
        fd = ::openat(parent, leaf.c_str(), O_DIRECTORY | O_RDONLY | O_NOFOLLOW | O_CLOEXEC);
        int e = errno;
        struct stat st {};
        const bool link = fd < 0 && ::fstatat(parent, leaf.c_str(), &st, AT_SYMLINK_NOFOLLOW) == 0 && S_ISLNK(st.st_mode);
        ::close(parent);
        if (fd < 0) err = link ? file_error::kAccessDenied : fromErrno(e);
    }
    if (fd < 0) return 0;
    DIR* d = ::fdopendir(fd);
    if (!d) {
        ::close(fd);
        err = file_error::kDeviceError;
        return 0;
    }
    Listing listing;
    listing.open = true;
    while (const dirent* e = ::readdir(d)) {
        std::string name = e->d_name;
        if (name == "." || name == "..") continue;
        DirEntry entry;
        entry.name = name;
        struct stat st {};
        if (::fstatat(::dirfd(d), name.c_str(), &st, AT_SYMLINK_NOFOLLOW) == 0) {
            entry.directory = S_ISDIR(st.st_mode);
            entry.size = S_ISREG(st.st_mode) ? static_cast<uint64_t>(st.st_size) : 0;
            entry.modified = static_cast<int64_t>(st.st_mtime);
        }
        listing.entries.push_back(std::move(entry));
    }
    ::closedir(d);
    std::sort(listing.entries.begin(), listing.entries.end(), [](const DirEntry& a, const DirEntry& b) { return a.name < b.name; });
    if (slot == dirs_.size()) dirs_.push_back(std::move(listing));
    else dirs_[slot] = std::move(listing);
    return static_cast<uint32_t>(slot + 1);
}

bool FileSandbox::nextEntry(uint32_t handle, DirEntry& entry, uint32_t& err) {
    err = 0;
    if (handle == 0 || handle > dirs_.size() || !dirs_[handle - 1].open) {
        err = file_error::kInvalidParam;
        return false;
    }
    Listing& l = dirs_[handle - 1];
    if (l.next >= l.entries.size()) return false;
    entry = l.entries[l.next++];
    return true;
}

const FileSandbox::DirEntry* FileSandbox::lastEntry(uint32_t handle) const {
    if (handle == 0 || handle > dirs_.size() || !dirs_[handle - 1].open) return nullptr;
    const Listing& l = dirs_[handle - 1];
    return l.next == 0 ? nullptr : &l.entries[l.next - 1];
}

uint32_t FileSandbox::closeDir(uint32_t handle) {
    if (handle == 0 || handle > dirs_.size() || !dirs_[handle - 1].open) return file_error::kInvalidParam;
    dirs_[handle - 1] = Listing{};
    return 0;
}

}  // namespace strun::rt
