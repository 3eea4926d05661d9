// The native work of Tc2_System's file blocks (stdlib/libraries/Tc2_System/
// files.st): each F_strun_File* call does one operation in the --files
// sandbox (runtime/file_sandbox.h) at once and returns its result, a
// negative number being minus the ADS error code. The blocks around them
// give TwinCAT's bExecute / bBusy / bError / nErrId behaviour (decision 0221).
#include <algorithm>
#include <cstring>
#include <string>

#include <fmt/format.h>

#include "interpreter/builtins/libraries/library_natives.h"
#include "interpreter/builtins/string_nodes.h"
#include "interpreter/exec/value_nodes.h"
#include "runtime/file_sandbox.h"

namespace strun::stdlib::bind {

namespace {

using exec::Ctx;

enum class FileOp : uint8_t {
    Open, Close, Read, Write, Gets, Puts, Seek, Tell, Eof, Delete, Rename, CreateDir, RemoveDir,
    DirOpen, DirNext, DirEntrySize, DirEntryIsDir, DirEntryTime, DirClose  // CAA File's directory listing
};

struct FileOpNode final : exec::Expr {
    FileOp op;
    Expr* a;
    Expr* b;
    Expr* c3;
    exec::Site site;
    FileOpNode(FileOp o, Expr* x, Expr* y, Expr* z, exec::Site s) : op(o), a(x), b(y), c3(z), site(s) {}

    static int64_t result(uint32_t err, int64_t ok) { return err ? -static_cast<int64_t>(err) : ok; }
    static uint8_t* address(int64_t v) { return reinterpret_cast<uint8_t*>(static_cast<intptr_t>(v)); }

    // The buffer [p, p + n) must be the project's memory (as MEMCPY's). A
    // null buffer is the block's error (1803), not a fault.
    bool inside(Ctx& c, const uint8_t* p, uint64_t n) {
        if (n == 0) return true;
        if (!p) return false;
        if (c.m->memory.contains(p, n)) return true;
        exec::reportMemoryFault(c, site, fmt::format("file block: the buffer of {} bytes lies outside the project's memory", n));
        return false;
    }

    int64_t i(Ctx& c) override {
        rt::FileSandbox& box = rt::fileSandbox();
        auto handle = [&] { return static_cast<uint32_t>(a->i(c)); };
        switch (op) {
            case FileOp::Open: {
                uint32_t err = 0;
                uint32_t h = box.open(viewOf<char>(a, c), static_cast<uint32_t>(b->i(c)), err);
                return result(err, h);
            }
            case FileOp::Close: return result(box.close(handle()), 0);
            case FileOp::Read:
            case FileOp::Write: {
                uint32_t h = handle();
                uint8_t* p = address(b->i(c));
                auto n = static_cast<uint32_t>(c3->i(c));
                if (!inside(c, p, n)) return -static_cast<int64_t>(rt::file_error::kInvalidParam);
                uint32_t done = 0;
                bool eof = false;
                uint32_t err = op == FileOp::Read ? box.read(h, p, n, done, eof) : box.write(h, p, n, done);
                return result(err, done);
            }
            case FileOp::Gets: {
                uint32_t h = handle();
                uint8_t* p = address(b->i(c));
                auto n = static_cast<uint32_t>(c3->i(c));  // the buffer's size, terminator included
                if (n == 0 || !inside(c, p, n)) return -static_cast<int64_t>(rt::file_error::kInvalidParam);
                std::string line;
                bool eof = false;
                uint32_t err = box.gets(h, line, n - 1, eof);
                std::memcpy(p, line.data(), line.size());
                p[line.size()] = 0;
                return result(err, static_cast<int64_t>(line.size()));
            }
            case FileOp::Puts: {
                std::string_view s = viewOf<char>(b, c);
                uint32_t done = 0;
                return result(box.write(handle(), s.data(), static_cast<uint32_t>(s.size()), done), done);
            }
            case FileOp::Seek: return result(box.seek(handle(), b->i(c), static_cast<int>(c3->i(c))), 0);
            case FileOp::Tell: {
                int64_t pos = 0;
                uint32_t err = box.tell(handle(), pos);
                return result(err, pos);
            }
            case FileOp::Eof: {
                // At the end: the last read or line stopped there.
                uint32_t h = handle();
                uint8_t probe;
                uint32_t got = 0;
                bool eof = false;
                int64_t pos = 0;
                if (box.tell(h, pos) != 0) return 1;
                if (box.read(h, &probe, 1, got, eof) != 0) return 1;
                if (got == 1) box.seek(h, pos, 0);
                return got == 0 ? 1 : 0;
            }
            case FileOp::Delete: return result(box.remove(viewOf<char>(a, c)), 0);
            case FileOp::Rename: return result(box.rename(viewOf<char>(a, c), viewOf<char>(b, c)), 0);
            case FileOp::CreateDir: return result(box.makeDir(viewOf<char>(a, c)), 0);
            case FileOp::RemoveDir: return result(box.removeDir(viewOf<char>(a, c)), 0);
            case FileOp::DirOpen: {
                uint32_t err = 0;
                uint32_t h = box.openDir(viewOf<char>(a, c), err);
                return result(err, h);
            }
            case FileOp::DirNext: {
                // The next entry's name into [p, p + n) (cut to fit, always
                // terminated): 1, or 0 when no entry is left.
                uint32_t h = handle();
                uint8_t* p = address(b->i(c));
                auto n = static_cast<uint32_t>(c3->i(c));
                if (n == 0 || !inside(c, p, n)) return -static_cast<int64_t>(rt::file_error::kInvalidParam);
                rt::FileSandbox::DirEntry entry;
                uint32_t err = 0;
                if (!box.nextEntry(h, entry, err)) return result(err, 0);
                const size_t len = std::min<size_t>(entry.name.size(), n - 1);
                std::memcpy(p, entry.name.data(), len);
                p[len] = 0;
                return 1;
            }
            case FileOp::DirEntrySize:
            case FileOp::DirEntryIsDir:
            case FileOp::DirEntryTime: {
                const rt::FileSandbox::DirEntry* e = box.lastEntry(handle());
                if (!e) return 0;
                if (op == FileOp::DirEntrySize) return static_cast<int64_t>(e->size);
                if (op == FileOp::DirEntryIsDir) return e->directory ? 1 : 0;
                return e->modified;
            }
            case FileOp::DirClose: return result(box.closeDir(handle()), 0);
        }
        return 0;
    }
};

enum class Arg : uint8_t { Str, Int, Addr };

Checked argOf(Checker& ck, const Checked& a, Arg kind, const std::string& fn) {
    if (!a.ok) return a;
    switch (kind) {
        case Arg::Str:
            if (!isStringArg(a, false)) return argError(ck, a, fn, "expected a STRING");
            return a;
        case Arg::Int: return ck.coerce(a, ck.types().elementary(TK::LInt), a.loc, fn.c_str());
        case Arg::Addr:
            if (a.type && a.type->kind == TK::Pointer) return a;
            if (isIntegerArg(a) || isBitArg(a)) return ck.coerce(a, ck.types().elementary(TK::ULInt), a.loc, fn.c_str());
            return argError(ck, a, fn, "expected an address (ADR(...) or a POINTER)");
    }
    return a;
}

// A file operation's argument kinds (at most three), held by value in its BuiltinFn.
struct ArgKinds {
    Arg kind[3];
    size_t count;
    size_t size() const { return count; }
    Arg operator[](size_t k) const { return kind[k]; }
};

void addFileOp(Checker& ck, const char* name, FileOp op, std::initializer_list<Arg> kinds) {
    ArgKinds args{};
    for (Arg k : kinds) args.kind[args.count++] = k;
    struct FileOpData { FileOp op; ArgKinds args; };
    ck.addBuiltin(name, BuiltinFn([](Checker& ck, CallArgs& call, const BuiltinFn& self) -> Checked {
        const auto [op, args] = self.data<FileOpData>();
        std::vector<Checked> a;
        bool bound = args.size() == 1   ? bindFixed(ck, call, {{"A"}}, a)
                     : args.size() == 2 ? bindFixed(ck, call, {{"A"}, {"B"}}, a)
                                        : bindFixed(ck, call, {{"A"}, {"B"}, {"C"}}, a);
        if (!bound) return ck.bad(call.loc);
        exec::Expr* nodes[3] = {nullptr, nullptr, nullptr};
        for (size_t k = 0; k < args.size(); ++k) {
            Checked v = argOf(ck, a[k], args[k], call.name);
            if (!v.ok) return v;
            nodes[k] = v.node;
        }
        auto* n = ck.pool().make<FileOpNode>(op, nodes[0], nodes[1], nodes[2], ck.site(call.loc));
        const TK kind = op == FileOp::Eof || op == FileOp::DirEntryIsDir                 ? TK::Bool
                        : op == FileOp::DirEntrySize || op == FileOp::DirEntryTime ? TK::LInt
                                                                                   : TK::DInt;
        return makeResult(ck, n, ck.types().elementary(kind), call, a, false);
    }, FileOpData{op, args}));
}

}  // namespace

void registerTc2SystemFileNatives(Checker& ck) {
    addFileOp(ck, "F_STRUN_FILEOPEN", FileOp::Open, {Arg::Str, Arg::Int});
    addFileOp(ck, "F_STRUN_FILECLOSE", FileOp::Close, {Arg::Int});
    addFileOp(ck, "F_STRUN_FILEREAD", FileOp::Read, {Arg::Int, Arg::Addr, Arg::Int});
    addFileOp(ck, "F_STRUN_FILEWRITE", FileOp::Write, {Arg::Int, Arg::Addr, Arg::Int});
    addFileOp(ck, "F_STRUN_FILEGETS", FileOp::Gets, {Arg::Int, Arg::Addr, Arg::Int});
    addFileOp(ck, "F_STRUN_FILEPUTS", FileOp::Puts, {Arg::Int, Arg::Str});
    addFileOp(ck, "F_STRUN_FILESEEK", FileOp::Seek, {Arg::Int, Arg::Int, Arg::Int});
    addFileOp(ck, "F_STRUN_FILETELL", FileOp::Tell, {Arg::Int});
    addFileOp(ck, "F_STRUN_FILEEOF", FileOp::Eof, {Arg::Int});
    addFileOp(ck, "F_STRUN_FILEDELETE", FileOp::Delete, {Arg::Str});
    addFileOp(ck, "F_STRUN_FILERENAME", FileOp::Rename, {Arg::Str, Arg::Str});
    addFileOp(ck, "F_STRUN_CREATEDIR", FileOp::CreateDir, {Arg::Str});
    addFileOp(ck, "F_STRUN_REMOVEDIR", FileOp::RemoveDir, {Arg::Str});
    addFileOp(ck, "F_STRUN_DIROPEN", FileOp::DirOpen, {Arg::Str});
    addFileOp(ck, "F_STRUN_DIRNEXT", FileOp::DirNext, {Arg::Int, Arg::Addr, Arg::Int});
    addFileOp(ck, "F_STRUN_DIRENTRYSIZE", FileOp::DirEntrySize, {Arg::Int});
    addFileOp(ck, "F_STRUN_DIRENTRYISDIR", FileOp::DirEntryIsDir, {Arg::Int});
    addFileOp(ck, "F_STRUN_DIRENTRYTIME", FileOp::DirEntryTime, {Arg::Int});
    addFileOp(ck, "F_STRUN_DIRCLOSE", FileOp::DirClose, {Arg::Int});
}

}  // namespace strun::stdlib::bind
