#include "interpreter/project/retain_store.h"

#include <algorithm>
#include <cerrno>
#include <climits>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string_view>
#include <unordered_map>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "interpreter/project/retain_validate.h"
#include "runtime/fnv1a.h"
#include "runtime/output_files.h"

namespace strun::project {

namespace {

using sema::TK;
using sema::Type;

constexpr const char* kMagic = "STRUN-RETAIN 1";
constexpr uint64_t kFnvBasis = rt::kRetainFnv1aBasis;

// No host addresses in the file: pointers, references and interfaces are
// not retained (their value means nothing in another run).
bool holdsAddress(const Type* t, int depth = 0) {
    if (!t || depth > 1100) return false;
    switch (t->kind) {
        case TK::Pointer: case TK::Reference: case TK::Interface: case TK::FunctionBlock: return true;
        case TK::Array: return holdsAddress(t->elem, depth + 1);
        case TK::Struct:
            for (const Type* p = t; p; p = p->parent)
                for (const auto& f : p->fields)
                    if (holdsAddress(f.type, depth + 1)) return true;
            return false;
        default: return false;
    }
}

bool holdsBlock(const Type* t, int depth = 0) {
    if (!t || depth > 1100) return false;
    if (t->kind == TK::FunctionBlock) return true;
    if (t->kind == TK::Array) return holdsBlock(t->elem, depth + 1);
    if (t->kind == TK::Struct)
        for (const Type* p = t; p; p = p->parent)
            for (const auto& f : p->fields)
                if (holdsBlock(f.type, depth + 1)) return true;
    return false;
}

// Reads a file in 64 KiB pieces: nothing of it is ever held whole.
class Reader {
public:
    explicit Reader(int fd) : fd_(fd), buffer_(new char[kSize]) {}
    int get() {
        if (at_ == end_ && !fill()) return -1;
        ++consumed_;
        return static_cast<unsigned char>(buffer_[at_++]);
    }
    uint64_t consumed() const { return consumed_; }
    int error() const { return error_; }

private:
    static constexpr size_t kSize = 1 << 16;
    bool fill() {
        ssize_t n;
        do n = ::read(fd_, buffer_.get(), kSize);
        while (n < 0 && errno == EINTR);
        if (n < 0) error_ = errno;
        if (n <= 0) return false;
        at_ = 0;
        end_ = static_cast<size_t>(n);
        return true;
    }
    int fd_;
    std::unique_ptr<char[]> buffer_;
    size_t at_ = 0, end_ = 0;
    uint64_t consumed_ = 0;
    int error_ = 0;
};

// Writes in 64 KiB pieces and keeps the checksum of what it wrote.
class Writer {
public:
    explicit Writer(int fd) : fd_(fd) { buffer_.reserve(kSize); }
    void put(std::string_view text) {
        for (unsigned char c : text) hash_ = rt::fnv1aStep(hash_, c);
        buffer_.append(text);
        if (buffer_.size() >= kSize) flush();
    }
    uint64_t hash() const { return hash_; }
    // Everything written; false (errno set) at the first failed write.
    bool finish() {
        flush();
        return ok_;
    }

private:
    static constexpr size_t kSize = 1 << 16;
    void flush() {
        size_t done = 0;
        while (ok_ && done < buffer_.size()) {
            ssize_t n = ::write(fd_, buffer_.data() + done, buffer_.size() - done);
            if (n < 0 && errno == EINTR) continue;
            if (n <= 0) {
                if (n == 0) errno = ENOSPC;
                ok_ = false;
                break;
            }
            done += static_cast<size_t>(n);
        }
        buffer_.clear();
    }
    int fd_;
    std::string buffer_;
    uint64_t hash_ = kFnvBasis;
    bool ok_ = true;
};

// The first pass over a retain file: its first line, its size against the
// limit, and the checksum on its last line (`END count sum`, the FNV-1a 64
// of every byte before that line). Values are restored only from a file
// that passes, so a damaged file never gives half its values.
struct Scan {
    enum Result { Good, NotRetainFile, Damaged, TooLarge, ReadError } result = Damaged;
    int error = 0;
};

Scan scanRetainFile(int fd, uint64_t limit, bool firstLineOnly) {
    Reader in(fd);
    const std::string_view magic = kMagic;
    uint64_t hash = kFnvBasis, hashAtLine = kFnvBasis, hashAtLast = kFnvBasis;
    std::string line, last;
    bool lineStart = true, firstLine = true;
    int c;
    while ((c = in.get()) >= 0) {
        if (lineStart) {
            hashAtLine = hash;
            line.clear();
            lineStart = false;
        }
        if (c == '\n') {
            if (firstLine) {
                if (line != magic) return {Scan::NotRetainFile};
                if (firstLineOnly) return {Scan::Good};
                firstLine = false;
            }
            last = line;
            hashAtLast = hashAtLine;
            lineStart = true;
        } else if (line.size() < 96) {
            line.push_back(static_cast<char>(c));
        }
        if (firstLine && (line.size() > magic.size() || magic.substr(0, line.size()) != line)) return {Scan::NotRetainFile};
        if (in.consumed() > limit) return {Scan::TooLarge};
        hash = rt::fnv1aStep(hash, static_cast<uint8_t>(c));
    }
    if (in.error()) return {Scan::ReadError, in.error()};
    if (in.consumed() == 0) return {Scan::Damaged};
    if (firstLine) return {line == magic.substr(0, line.size()) ? Scan::Damaged : Scan::NotRetainFile};
    if (!lineStart) {  // a last line without its newline
        last = line;
        hashAtLast = hashAtLine;
    }
    size_t count = 0;
    unsigned long long sum = 0;
    if (last.compare(0, 4, "END ") != 0 || std::sscanf(last.c_str(), "END %zu %llx", &count, &sum) != 2 || sum != hashAtLast)
        return {Scan::Damaged};
    return {Scan::Good};
}

}  // namespace

RetainStore::RetainStore(sema::ProgramModel& model, std::string path, std::ostream& warnings)
    : path_(std::move(path)), warnings_(warnings), target_(path_) {
    for (const sema::VarSym* g : model.globals)
        if (g->abs && g->bit < 0) collect(g->globalKey(), g->type, g->abs, g->retain, 0);
    for (auto& inst : model.programs) {
        for (const sema::PouInfo* p = inst.pou; p; p = p->parent)
            for (const auto& v : p->ownedVars)
                if (v->storage == sema::Storage::Self && !v->byRef)
                    collect(inst.name + "." + v->name, v->type, inst.memory + v->offset, v->retain, 0);
    }
    if (truncated_)
        warnings_ << "strun: warning: --retain: more than " << kMaxRetainedValues << " retained values; the rest is not kept\n";
}

void RetainStore::keepSystemWords(sema::ProgramModel& model, const std::vector<int>& words) {
    const Type* word = model.types->elementary(sema::TK::Word);
    for (int n : words) {
        if (n < 0 || size_t(n) >= rt::ProcessImage::kSystemWords) continue;
        values_.push_back({"%SW" + std::to_string(n), sema::typeName(word) + " (2 bytes)", &model.machine.image.systemWords[size_t(n) * 2], 2,
                           word});
    }
}

// Walks into FB instances (their members may be RETAIN) and, for retained
// storage, keeps whole blocks of plain data or descends where addresses are.
void RetainStore::collect(const std::string& path, const Type* t, uint8_t* addr, bool retained, int depth) {
    if (!t || !addr || depth > 1100) return;
    if (values_.size() >= kMaxRetainedValues) {
        truncated_ = true;
        return;
    }
    if (t->kind == TK::FunctionBlock && t->pou) {
        for (const sema::PouInfo* p = t->pou; p; p = p->parent)
            for (const auto& v : p->ownedVars)
                if (v->storage == sema::Storage::Self && !v->byRef)
                    collect(path + "." + v->name, v->type, addr + v->offset, retained || v->retain, depth + 1);
        return;
    }
    if (!retained && !holdsBlock(t)) return;
    if (retained && !holdsAddress(t)) {
        values_.push_back({path, sema::typeName(t) + " (" + std::to_string(t->size) + " bytes)", addr, t->size, t});
        return;
    }
    if (t->kind == TK::Array && t->elem && !t->flexible) {
        // Element paths by flat index: ARRAY[1..2, 1..3] element k is path[k].
        for (uint64_t k = 0; k < t->elemCount && !truncated_; ++k)
            collect(path + "[" + std::to_string(k) + "]", t->elem, addr + k * t->elem->size, retained, depth + 1);
    } else if (t->kind == TK::Struct) {
        for (const Type* p = t; p; p = p->parent)
            for (const auto& f : p->fields) collect(path + "." + f.name, f.type, addr + f.offset, retained, depth + 1);
    }
}

uint64_t RetainStore::sizeLimit() const {
    uint64_t bytes = std::strlen(kMagic) + 1 + 64;  // the magic and END lines
    for (const Value& v : values_) bytes += v.path.size() + v.tag.size() + 2 * uint64_t(v.size) + 3;
    return 2 * bytes + (uint64_t{1} << 20);
}

bool RetainStore::writeTo(int fd) const {
    Writer out(fd);
    out.put(kMagic);
    out.put("\n");
    static const char digits[] = "0123456789abcdef";
    char chunk[8192];
    for (const Value& v : values_) {
        out.put(v.path);
        out.put("\t");
        out.put(v.tag);
        out.put("\t");
        // The hex of a 256 MiB array is written in pieces, never built whole.
        for (uint32_t done = 0; done < v.size;) {
            const uint32_t n = std::min<uint32_t>(v.size - done, sizeof chunk / 2);
            for (uint32_t k = 0; k < n; ++k) {
                chunk[2 * k] = digits[v.addr[done + k] >> 4];
                chunk[2 * k + 1] = digits[v.addr[done + k] & 15];
            }
            out.put(std::string_view(chunk, 2 * n));
            done += n;
        }
        out.put("\n");
    }
    char end[64];
    std::snprintf(end, sizeof end, "END %zu %016llx\n", values_.size(), static_cast<unsigned long long>(out.hash()));
    out.put(end);
    return out.finish();
}

bool RetainStore::save(bool quiet) {
    const std::string temp = target_ + ".tmp";
    auto fail = [&](const char* what, const std::string& file) {
        if (!quiet) warnings_ << "strun: warning: --retain: cannot " << what << " '" << file << "': " << std::strerror(errno) << "\n";
        return false;
    };
    // FILE.tmp is strun's own: never a link followed, a FIFO waited on or a device written.
    int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC | O_NOFOLLOW | O_NONBLOCK, 0644);
    if (fd < 0) return fail("create", temp);
    struct stat st {};
    if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
        ::close(fd);
        errno = EINVAL;
        if (!quiet) warnings_ << "strun: warning: --retain: '" << temp << "' is not a regular file; nothing saved\n";
        return false;
    }
    if (!writeTo(fd)) {
        const int saved = errno;
        ::close(fd);
        ::unlink(temp.c_str());
        errno = saved;
        return fail("write", temp);
    }
    if (::fsync(fd) != 0) {
        const int saved = errno;
        ::close(fd);
        ::unlink(temp.c_str());
        errno = saved;
        return fail("sync", temp);
    }
    if (::close(fd) != 0) {
        ::unlink(temp.c_str());
        return fail("close", temp);
    }
    // Nothing is renamed over what is not a regular file (a device or FIFO put there during the run).
    if (::lstat(target_.c_str(), &st) == 0 && !S_ISREG(st.st_mode)) {
        ::unlink(temp.c_str());
        if (!quiet) warnings_ << "strun: warning: --retain: '" << target_ << "' is no longer a regular file; nothing saved\n";
        return false;
    }
    if (::rename(temp.c_str(), target_.c_str()) != 0) return fail("rename", temp);
    // Make the rename itself durable.
    std::string dir = target_.find('/') == std::string::npos ? "." : target_.substr(0, target_.rfind('/') + 1);
    int dfd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (dfd >= 0) {
        ::fsync(dfd);
        ::close(dfd);
    }
    return true;
}

bool RetainStore::start(bool cold, const std::vector<std::string>& inputs, std::string& error) {
    error = rt::outputPathProblem("--retain", path_, inputs);
    if (!error.empty()) return false;
    struct stat st {};
    if (::lstat(path_.c_str(), &st) != 0) return true;  // no file yet: cold start
    if (S_ISLNK(st.st_mode)) {
        // A link is kept: the file it leads to is the one replaced.
        if (char* real = ::realpath(path_.c_str(), nullptr)) {
            target_ = real;
            std::free(real);
        }
    }
    if (::stat(target_.c_str(), &st) != 0) return true;  // a link to nowhere: the file is made there
    const int fd = rt::openRegularInput(target_, error);
    if (fd < 0) {
        error = "--retain: " + error;
        return false;
    }
    const Scan scan = scanRetainFile(fd, sizeLimit(), cold);
    if (scan.result == Scan::ReadError) {
        error = "--retain: cannot read '" + path_ + "': " + std::strerror(scan.error);
    } else if (scan.result == Scan::NotRetainFile && !cold) {
        error = "--retain: '" + path_ + "' is not a retain file (it does not start with the line '" + kMagic +
                "'); strun does not overwrite it (--cold replaces it)";
    } else if (!cold) {
        if (scan.result == Scan::TooLarge)
            warnings_ << "strun: warning: --retain: '" << path_ << "' is larger than the " << sizeLimit()
                      << " bytes a retain file of this project can have; cold start\n";
        else if (scan.result == Scan::Damaged)
            warnings_ << "strun: warning: --retain: '" << path_ << "' is not a complete retain file; cold start\n";
        else if (::lseek(fd, 0, SEEK_SET) == 0)
            restore(fd);
    }
    ::close(fd);
    return error.empty();
}

// The second pass over a file whose checksum is right: each value line is
// taken in pieces (a value's hex can be hundreds of MiB), decoded into one
// buffer, checked against the variable's type and only then copied.
void RetainStore::restore(int fd) {
    std::unordered_map<std::string_view, const Value*> byPath;
    size_t longestPath = 0, longestTag = 0;
    for (const Value& v : values_) {
        byPath.emplace(v.path, &v);
        longestPath = std::max(longestPath, v.path.size());
        longestTag = std::max(longestTag, v.tag.size());
    }
    Reader in(fd);
    size_t warned = 0;
    auto warn = [&](const std::string& message) {
        if (warned++ < 20) warnings_ << "strun: warning: --retain: " << message << "\n";
    };
    // A field up to TAB; one longer than any variable's (and than a warning shows) is cut: it matches nothing.
    auto field = [&](std::string& out, size_t longest) {
        out.clear();
        const size_t keep = std::max<size_t>(longest + 1, 256);
        int c;
        while ((c = in.get()) >= 0 && c != '\t' && c != '\n')
            if (out.size() < keep) out.push_back(char(c));
        return c;
    };
    auto skipLine = [&] {
        int c;
        while ((c = in.get()) >= 0 && c != '\n') {
        }
    };
    auto shown = [](std::string s) { return s.size() > 200 ? s.substr(0, 200) + "..." : s; };
    skipLine();  // the magic line
    std::string path, tag, why;
    std::vector<uint8_t> bytes;
    while (true) {
        const int c = field(path, std::max<size_t>(longestPath, 4));
        if (c < 0 || (c == '\n' && path.compare(0, 4, "END ") == 0)) break;  // the END line (checked by the scan)
        if (c == '\n') continue;  // not a value line
        auto it = byPath.find(path);
        if (it == byPath.end()) {
            warn("'" + shown(path) + "' is no longer a retained variable; its saved value is dropped");
            skipLine();
            continue;
        }
        const Value& v = *it->second;
        if (field(tag, longestTag) != '\t' || tag != v.tag) {
            warn("'" + path + "' was " + shown(tag) + " and is now " + v.tag + "; it starts from its initial value");
            skipLine();
            continue;
        }
        bytes.resize(v.size);
        bool ok = true;
        uint64_t digits = 0;
        int h;
        while ((h = in.get()) >= 0 && h != '\n') {
            const int nibble = h >= '0' && h <= '9' ? h - '0' : h >= 'a' && h <= 'f' ? h - 'a' + 10 : -1;
            if (nibble < 0 || digits >= 2 * uint64_t(v.size)) {
                ok = false;
                continue;
            }
            uint8_t& b = bytes[digits / 2];
            b = digits % 2 ? uint8_t(b | nibble) : uint8_t(nibble << 4);
            ++digits;
        }
        if (!ok || digits != 2 * uint64_t(v.size)) {
            warn("'" + path + "': the saved bytes do not fit " + v.tag + "; it starts from its initial value");
            continue;
        }
        if (!validRetainedValue(v.type, bytes.data(), why)) {
            warn("'" + path + "': the saved value is not a valid " + sema::typeName(v.type) + " (" + why +
                 "); it starts from its initial value");
            continue;
        }
        std::memcpy(v.addr, bytes.data(), v.size);
    }
    if (warned > 20) warnings_ << "strun: warning: --retain: " << (warned - 20) << " further warnings suppressed\n";
}

}  // namespace strun::project
