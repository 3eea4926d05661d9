#include "interpreter/project/retain_store.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>

#include <fcntl.h>
#include <unistd.h>

namespace strun::project {

namespace {

using sema::TK;
using sema::Type;

constexpr const char* kMagic = "STRUN-RETAIN 1";

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

uint64_t fnv1a(const std::string& s) {
    uint64_t h = 1469598103934665603ull;
    for (unsigned char c : s) {
        h ^= c;
        h *= 1099511628211ull;
    }
    return h;
}

std::string hex(const uint8_t* p, size_t n) {
    static const char digits[] = "0123456789abcdef";
    std::string out(n * 2, '0');
    for (size_t k = 0; k < n; ++k) {
        out[2 * k] = digits[p[k] >> 4];
        out[2 * k + 1] = digits[p[k] & 15];
    }
    return out;
}

bool unhex(const std::string& text, std::vector<uint8_t>& out) {
    if (text.size() % 2) return false;
    out.resize(text.size() / 2);
    for (size_t k = 0; k < out.size(); ++k) {
        auto nibble = [](char c) -> int {
            if (c >= '0' && c <= '9') return c - '0';
            if (c >= 'a' && c <= 'f') return c - 'a' + 10;
            return -1;
        };
        int hi = nibble(text[2 * k]), lo = nibble(text[2 * k + 1]);
        if (hi < 0 || lo < 0) return false;
        out[k] = static_cast<uint8_t>(hi << 4 | lo);
    }
    return true;
}

}  // namespace

RetainStore::RetainStore(sema::ProgramModel& model, std::string path, std::ostream& warnings)
    : path_(std::move(path)), warnings_(warnings) {
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
        values_.push_back({path, sema::typeName(t) + " (" + std::to_string(t->size) + " bytes)", addr, t->size});
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

std::string RetainStore::serialize() const {
    std::string body = std::string(kMagic) + "\n";
    for (const Value& v : values_) body += v.path + "\t" + v.tag + "\t" + hex(v.addr, v.size) + "\n";
    char end[64];
    std::snprintf(end, sizeof end, "END %zu %016llx\n", values_.size(), static_cast<unsigned long long>(fnv1a(body)));
    return body + end;
}

bool RetainStore::save() {
    const std::string text = serialize();
    const std::string temp = path_ + ".tmp";
    auto fail = [&](const char* what) {
        warnings_ << "strun: warning: --retain: cannot " << what << " '" << temp << "': " << std::strerror(errno) << "\n";
        return false;
    };
    int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (fd < 0) return fail("create");
    size_t done = 0;
    while (done < text.size()) {
        ssize_t n = ::write(fd, text.data() + done, text.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            ::close(fd);
            return fail("write");
        }
        done += static_cast<size_t>(n);
    }
    if (::fsync(fd) != 0) {
        ::close(fd);
        return fail("sync");
    }
    ::close(fd);
    if (::rename(temp.c_str(), path_.c_str()) != 0) return fail("rename");
    // Make the rename itself durable.
    std::string dir = path_.find('/') == std::string::npos ? "." : path_.substr(0, path_.rfind('/') + 1);
    int dfd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (dfd >= 0) {
        ::fsync(dfd);
        ::close(dfd);
    }
    return true;
}

void RetainStore::restore() {
    std::ifstream in(path_, std::ios::binary);
    if (!in) return;  // no file yet: cold start
    std::stringstream ss;
    ss << in.rdbuf();
    const std::string text = ss.str();
    // The checksum line closes the file; anything else is a damaged file.
    const size_t endAt = text.rfind("END ");
    unsigned long long sum = 0;
    size_t count = 0;
    if (text.compare(0, std::strlen(kMagic) + 1, std::string(kMagic) + "\n") != 0 || endAt == std::string::npos ||
        std::sscanf(text.c_str() + endAt, "END %zu %llx", &count, &sum) != 2 || fnv1a(text.substr(0, endAt)) != sum) {
        warnings_ << "strun: warning: --retain: '" << path_ << "' is not a complete retain file; cold start\n";
        return;
    }
    std::map<std::string, const Value*> byPath;
    for (const Value& v : values_) byPath[v.path] = &v;
    std::istringstream lines(text.substr(0, endAt));
    std::string line;
    std::getline(lines, line);  // the magic line
    size_t warned = 0, restored = 0;
    auto warn = [&](const std::string& message) {
        if (warned++ < 20) warnings_ << "strun: warning: --retain: " << message << "\n";
    };
    std::vector<uint8_t> bytes;
    while (std::getline(lines, line)) {
        size_t a = line.find('\t'), b = line.find('\t', a == std::string::npos ? a : a + 1);
        if (a == std::string::npos || b == std::string::npos) continue;
        const std::string path = line.substr(0, a), tag = line.substr(a + 1, b - a - 1);
        auto it = byPath.find(path);
        if (it == byPath.end()) {
            warn("'" + path + "' is no longer a retained variable; its saved value is dropped");
            continue;
        }
        const Value& v = *it->second;
        if (v.tag != tag || !unhex(line.substr(b + 1), bytes) || bytes.size() != v.size) {
            warn("'" + path + "' was " + tag + " and is now " + v.tag + "; it starts from its initial value");
            continue;
        }
        std::memcpy(v.addr, bytes.data(), v.size);
        ++restored;
    }
    if (warned > 20) warnings_ << "strun: warning: --retain: " << (warned - 20) << " further warnings suppressed\n";
}

}  // namespace strun::project
