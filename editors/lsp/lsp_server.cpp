#include "editors/lsp/lsp_server.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <thread>

#include "cli/diagnostic_render.h"
#include "editors/lsp/lsp_text.h"
#include "interpreter/source/project_inputs.h"
#include "interpreter/source/read_source.h"
#include "runtime/plc_profile.h"

namespace strun::editors::lsp {

namespace fs = std::filesystem;
using json = nlohmann::json;

namespace {

// JSON-RPC and LSP error codes.
constexpr int kParseError = -32700;
constexpr int kInvalidRequest = -32600;
constexpr int kMethodNotFound = -32601;
constexpr int kInvalidParams = -32602;
constexpr int kInternalError = -32603;
constexpr int kServerNotInitialized = -32002;

std::string normalPath(const std::string& path) {
    if (path.empty()) return path;
    std::error_code ec;
    fs::path p = fs::absolute(fs::path(path), ec);
    if (ec) p = fs::path(path);
    return p.lexically_normal().string();
}

int codePoints(std::string_view s) {
    int n = 0;
    for (unsigned char c : s)
        if ((c & 0xC0) != 0x80) ++n;
    return n;
}

// LSP SymbolKind / CompletionItemKind of a symbol.
int symbolKindNumber(SymbolKind k) {
    switch (k) {
        case SymbolKind::Program: return 2;        // Module
        case SymbolKind::Function: return 12;      // Function
        case SymbolKind::FunctionBlock: return 5;  // Class
        case SymbolKind::Method: return 6;         // Method
        case SymbolKind::Action: return 6;         // Method
        case SymbolKind::Property: return 7;       // Property
        case SymbolKind::Interface: return 11;     // Interface
        case SymbolKind::Struct: return 23;        // Struct
        case SymbolKind::Enum: return 10;          // Enum
        case SymbolKind::Alias: return 26;         // TypeParameter
        case SymbolKind::EnumValue: return 22;     // EnumMember
        case SymbolKind::Variable: return 13;      // Variable
        case SymbolKind::Field: return 8;          // Field
        case SymbolKind::GlobalList: return 3;     // Namespace
        case SymbolKind::Configuration: return 4;  // Package
    }
    return 13;
}

int completionKindNumber(SymbolKind k) {
    switch (k) {
        case SymbolKind::Program: return 9;        // Module
        case SymbolKind::Function: return 3;       // Function
        case SymbolKind::FunctionBlock: return 7;  // Class
        case SymbolKind::Method:
        case SymbolKind::Action: return 2;         // Method
        case SymbolKind::Property: return 10;      // Property
        case SymbolKind::Interface: return 8;      // Interface
        case SymbolKind::Struct: return 22;        // Struct
        case SymbolKind::Enum: return 13;          // Enum
        case SymbolKind::Alias: return 25;         // TypeParameter
        case SymbolKind::EnumValue: return 20;     // EnumMember
        case SymbolKind::Variable: return 6;       // Variable
        case SymbolKind::Field: return 5;          // Field
        case SymbolKind::GlobalList: return 9;     // Module
        case SymbolKind::Configuration: return 9;  // Module
    }
    return 6;
}

const char* kindWord(const Symbol& s) {
    switch (s.section) {
        case ast::VarSection::Input: return "VAR_INPUT";
        case ast::VarSection::Output: return "VAR_OUTPUT";
        case ast::VarSection::InOut: return "VAR_IN_OUT";
        case ast::VarSection::Temp: return "VAR_TEMP";
        case ast::VarSection::Global: return "VAR_GLOBAL";
        case ast::VarSection::External: return "VAR_EXTERNAL";
        case ast::VarSection::Stat: return "VAR_STAT";
        case ast::VarSection::Inst: return "VAR_INST";
        default: return "VAR";
    }
}

const char* const kKeywords[] = {
    "IF", "THEN", "ELSIF", "ELSE", "END_IF", "CASE", "OF", "END_CASE", "FOR", "TO", "BY", "DO", "END_FOR", "WHILE",
    "END_WHILE", "REPEAT", "UNTIL", "END_REPEAT", "RETURN", "EXIT", "CONTINUE", "JMP", "VAR", "VAR_INPUT", "VAR_OUTPUT",
    "VAR_IN_OUT", "VAR_TEMP", "VAR_GLOBAL", "VAR_EXTERNAL", "VAR_STAT", "VAR_INST", "VAR_GENERIC", "END_VAR", "CONSTANT", "RETAIN",
    "PERSISTENT", "AT", "PROGRAM", "END_PROGRAM", "FUNCTION", "END_FUNCTION", "FUNCTION_BLOCK", "END_FUNCTION_BLOCK",
    "METHOD", "END_METHOD", "ACTION", "END_ACTION", "PROPERTY", "END_PROPERTY", "INTERFACE", "END_INTERFACE", "EXTENDS",
    "IMPLEMENTS", "TYPE", "END_TYPE", "STRUCT", "END_STRUCT", "UNION", "END_UNION", "ARRAY", "POINTER", "REFERENCE",
    "REF", "THIS", "SUPER", "TRUE", "FALSE", "AND", "AND_THEN", "OR", "OR_ELSE", "XOR", "NOT", "MOD", "CONFIGURATION",
    "END_CONFIGURATION", "RESOURCE", "END_RESOURCE", "TASK", "WITH", "BOOL", "SINT", "INT", "DINT", "LINT", "USINT",
    "UINT", "UDINT", "ULINT", "BYTE", "WORD", "DWORD", "LWORD", "REAL", "LREAL", "TIME", "LTIME", "DATE", "TIME_OF_DAY",
    "TOD", "DATE_AND_TIME", "DT", "STRING", "WSTRING", "CHAR", "WCHAR",
};

bool isWordChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || static_cast<unsigned char>(c) >= 0x80; }

// The dotted chain written before `end` in `text` ("a.b[i]." -> {"a", "b[i]"}
// when the text before `end` is "a.b[i]"); empty when there is none.
std::vector<std::string> chainBefore(std::string_view text, size_t end) {
    std::vector<std::string> parts;
    size_t i = end;
    for (;;) {
        size_t stop = i;
        // Selectors after a name: [..] and ^.
        while (i > 0 && (text[i - 1] == '^' || text[i - 1] == ']')) {
            if (text[i - 1] == '^') { --i; continue; }
            int depth = 0;
            size_t k = i;
            while (k > 0) {
                --k;
                if (text[k] == ']') ++depth;
                else if (text[k] == '[' && --depth == 0) break;
            }
            if (depth != 0) return {};
            i = k;
        }
        size_t startName = i;
        while (startName > 0 && isWordChar(text[startName - 1])) --startName;
        if (startName == i) return parts.empty() ? parts : std::vector<std::string>{};
        parts.insert(parts.begin(), std::string(text.substr(startName, stop - startName)));
        i = startName;
        if (i > 0 && text[i - 1] == '.') {
            --i;
            continue;
        }
        return parts;
    }
}

}  // namespace

LspServer::LspServer(std::FILE* in, std::FILE* out) : reader_(in), writer_(out) {}

void LspServer::readLoop() {
    for (;;) {
        Incoming incoming;
        const bool more = reader_.next(incoming);
        std::lock_guard<std::mutex> lock(queueMutex_);
        if (!more) {
            inputEnded_ = true;
            queueReady_.notify_one();
            return;
        }
        queue_.push_back(std::move(incoming));
        queueReady_.notify_one();
    }
}

int LspServer::run() {
    // Reading on its own thread lets a burst of edits be compiled once.
    std::thread([this] { readLoop(); }).detach();
    for (;;) {
        Incoming incoming;
        {
            std::unique_lock<std::mutex> lock(queueMutex_);
            if (queue_.empty() && dirty_) {
                lock.unlock();
                recompile();
                publishDiagnostics();
                retire();
                continue;
            }
            queueReady_.wait(lock, [&] { return !queue_.empty() || inputEnded_; });
            if (queue_.empty()) break;
            incoming = std::move(queue_.front());
            queue_.pop_front();
        }
        if (!incoming.message) {
            replyError(nullptr, kParseError, incoming.error);
            continue;
        }
        handle(*incoming.message);
        if (exitRequested_) return shutdown_ ? 0 : 1;
    }
    return shutdown_ ? 0 : 1;
}

void LspServer::handle(const json& message) {
    const bool hasId = message.contains("id");
    json id = hasId ? message["id"] : json(nullptr);
    if (hasId && !id.is_string() && !id.is_number_integer() && !id.is_null()) {
        replyError(nullptr, kInvalidRequest, "the id must be a number or a string");
        return;
    }
    auto method = message.find("method");
    if (method == message.end()) {
        if (!hasId) replyError(nullptr, kInvalidRequest, "a message without a method");
        return;  // a response to a request of ours: none are sent
    }
    if (!method->is_string()) {
        if (hasId) replyError(id, kInvalidRequest, "the method must be a string");
        return;
    }
    const std::string name = method->get<std::string>();
    const json params = message.contains("params") ? message["params"] : json::object();
    if (!initialized_ && name != "initialize" && name != "exit") {
        if (hasId) replyError(id, kServerNotInitialized, "the server has not been initialized");
        return;
    }
    if (shutdown_ && name != "exit") {
        if (hasId) replyError(id, kInvalidRequest, "the server is shutting down");
        return;
    }
    // Requests read the project as edited so far.
    const bool isRequest = hasId;
    if (isRequest && dirty_ && name != "shutdown") {
        recompile();
        publishDiagnostics();
        retire();
    }
    bool notification = !hasId;
    try {
        json result = dispatch(name, params, notification);
        if (hasId) {
            if (result.is_discarded()) replyError(id, kMethodNotFound, "unknown method '" + name + "'");
            else reply(id, std::move(result));
        }
    } catch (const json::exception& e) {
        if (hasId) replyError(id, kInvalidParams, std::string("invalid parameters: ") + e.what());
    } catch (const std::bad_alloc&) {
        if (hasId) replyError(id, kInternalError, "out of memory");
    } catch (const std::exception& e) {
        if (hasId) replyError(id, kInternalError, e.what());
    }
}

json LspServer::dispatch(const std::string& method, const json& params, bool&) {
    if (method == "initialize") return initialize(params);
    if (method == "initialized") return nullptr;
    if (method == "shutdown") {
        shutdown_ = true;
        return nullptr;
    }
    if (method == "exit") {
        exitRequested_ = true;
        return nullptr;
    }
    if (method == "textDocument/didOpen") { didOpen(params); return nullptr; }
    if (method == "textDocument/didChange") { didChange(params); return nullptr; }
    if (method == "textDocument/didClose") { didClose(params); return nullptr; }
    if (method == "textDocument/didSave" || method == "workspace/didChangeWatchedFiles") {
        dirty_ = true;
        return nullptr;
    }
    if (method == "textDocument/hover") return hover(params);
    if (method == "textDocument/definition") return definition(params);
    if (method == "textDocument/references") return references(params);
    if (method == "textDocument/documentSymbol") return documentSymbol(params);
    if (method == "textDocument/completion") return completion(params);
    if (method == "textDocument/signatureHelp") return signatureHelp(params);
    if (method == "workspace/didChangeConfiguration" || method.rfind("$/", 0) == 0) return nullptr;
    return json(json::value_t::discarded);
}

json LspServer::initialize(const json& params) {
    initialized_ = true;
    if (params.is_object()) {
        std::string rootUri;
        if (params.contains("workspaceFolders") && params["workspaceFolders"].is_array() && !params["workspaceFolders"].empty() &&
            params["workspaceFolders"][0].is_object() && params["workspaceFolders"][0].value("uri", json()).is_string())
            rootUri = params["workspaceFolders"][0]["uri"].get<std::string>();
        else if (params.contains("rootUri") && params["rootUri"].is_string())
            rootUri = params["rootUri"].get<std::string>();
        if (!rootUri.empty()) root_ = normalPath(pathOfUri(rootUri));
        else if (params.contains("rootPath") && params["rootPath"].is_string()) root_ = normalPath(params["rootPath"].get<std::string>());
        if (params.contains("initializationOptions") && params["initializationOptions"].is_object()) {
            const json& o = params["initializationOptions"];
            if (o.contains("target") && o["target"].is_string()) {
                const std::string target = o["target"].get<std::string>();
                if (rt::findProfile(target)) options_.target = rt::findProfile(target)->id;
                else
                    notify("window/showMessage", {{"type", 1}, {"message", "strun lsp: unknown target '" + target + "'; using generic"}});
            }
            if (o.contains("strict") && o["strict"].is_boolean()) options_.strict = o["strict"].get<bool>();
        }
    }
    dirty_ = true;
    json capabilities = {
        {"positionEncoding", "utf-16"},
        {"textDocumentSync", {{"openClose", true}, {"change", 2}, {"save", {{"includeText", false}}}}},
        {"hoverProvider", true},
        {"definitionProvider", true},
        {"referencesProvider", true},
        {"documentSymbolProvider", true},
        {"completionProvider", {{"triggerCharacters", {"."}}, {"resolveProvider", false}}},
        {"signatureHelpProvider", {{"triggerCharacters", {"(", ","}}, {"retriggerCharacters", {","}}}},
    };
    return {{"capabilities", capabilities}, {"serverInfo", {{"name", "strun"}, {"version", STRUN_VERSION}}}};
}

// ---------------------------------------------------------------- documents

void LspServer::didOpen(const json& params) {
    const json& doc = params.at("textDocument");
    const std::string uri = doc.at("uri").get<std::string>();
    const std::string path = pathOfUri(uri);
    if (path.empty()) return;
    Document d;
    d.uri = uri;
    d.text = doc.at("text").get<std::string>();
    d.version = doc.value("version", int64_t{0});
    documents_[normalPath(path)] = std::move(d);
    dirty_ = true;
}

void LspServer::didChange(const json& params) {
    const json& doc = params.at("textDocument");
    const std::string path = pathOfUri(doc.at("uri").get<std::string>());
    auto it = documents_.find(normalPath(path));
    if (it == documents_.end()) return;
    Document& d = it->second;
    d.version = doc.value("version", d.version);
    for (const json& change : params.at("contentChanges")) {
        if (!change.contains("range") || change["range"].is_null()) {
            d.text = change.at("text").get<std::string>();
            continue;
        }
        // An incremental change: the range in UTF-16 positions.
        auto offsetOf = [&](const json& pos) {
            const int line = pos.at("line").get<int>();
            const int character = pos.at("character").get<int>();
            size_t start = 0;
            for (int l = 0; l < line; ++l) {
                const size_t nl = d.text.find('\n', start);
                if (nl == std::string::npos) return d.text.size();
                start = nl + 1;
            }
            size_t end = d.text.find('\n', start);
            if (end == std::string::npos) end = d.text.size();
            std::string_view lineText(d.text.data() + start, end - start);
            return start + byteOfColumn(lineText, columnOfCharacter(lineText, character));
        };
        size_t from = offsetOf(change.at("range").at("start"));
        size_t to = offsetOf(change.at("range").at("end"));
        if (to < from) std::swap(from, to);
        d.text.replace(from, to - from, change.at("text").get<std::string>());
    }
    dirty_ = true;
}

void LspServer::didClose(const json& params) {
    const std::string uri = params.at("textDocument").at("uri").get<std::string>();
    documents_.erase(normalPath(pathOfUri(uri)));
    publishEmpty(uri);
    dirty_ = true;
}

std::string LspServer::documentText(const std::string& key) const {
    auto it = documents_.find(key);
    return it == documents_.end() ? std::string() : it->second.text;
}

// ---------------------------------------------------------------- compiling

void LspServer::recompile() {
    dirty_ = false;
    std::vector<std::string> paths;
    if (!root_.empty()) {
        std::error_code ec;
        if (fs::is_directory(root_, ec)) {
            fs::recursive_directory_iterator it(root_, fs::directory_options::skip_permission_denied, ec), end;
            for (; !ec && it != end; it.increment(ec)) {
                const std::string name = it->path().filename().string();
                if (it->is_directory(ec) && (name == "node_modules" || (!name.empty() && name[0] == '.'))) {
                    it.disable_recursion_pending();
                    continue;
                }
                if (it->is_regular_file(ec) && source::isProjectSource(it->path().string())) paths.push_back(normalPath(it->path().string()));
            }
        }
    }
    for (const auto& [key, doc] : documents_)
        if (std::find(paths.begin(), paths.end(), key) == paths.end()) paths.push_back(key);
    std::sort(paths.begin(), paths.end());
    // The standard library is parsed once per server; its files come first.
    if (!library_) {
        CompileLog libraryLog;
        library_ = project::parseLibrary(libraryLog);
    }
    auto sources = std::make_unique<SourceSet>(library_->sources);
    std::vector<int> userFiles;
    CompileLog log;
    size_t bytes = 0;
    for (const std::string& path : paths) {
        std::string text;
        auto open = documents_.find(path);
        if (open != documents_.end()) {
            text = open->second.text;
            if (text.size() > kMaxSourceFileBytes) {
                notify("window/logMessage", {{"type", 2}, {"message", "strun lsp: " + path + " is larger than the source size limit"}});
                continue;
            }
        } else {
            std::string error;
            if (!readSourceText(path, bytes, text, error)) continue;  // unreadable or past the limits: left out
        }
        bytes += text.size();
        source::addProjectSourceText(path, std::move(text), *sources, userFiles, log);
    }
    // The previous compile is freed after the diagnostics are out (freeing a
    // large project's model is a sixth of compiling it).
    retired_ = std::move(current_);
    // Only the files whose text changed are parsed again (decision 0270).
    auto units = parsed_.units(*sources, userFiles, log);
    current_ = std::make_shared<ProjectIndex>(std::move(sources), std::move(userFiles), std::move(log), options_, *library_, std::move(units));
    if (current_->checked()) lastChecked_ = current_;
}

void LspServer::publishDiagnostics() {
    if (!current_) return;
    const SourceSet& sources = current_->sources();
    const std::vector<Diagnostic> shown = cli::shownDiagnostics(current_->log(), sources, cli::DiagnosticOptions{});
    for (const auto& [key, doc] : documents_) {
        json list = json::array();
        for (const Diagnostic& d : shown) {
            if (d.loc.file < 0 || d.loc.file >= sources.size() || normalPath(sources.file(d.loc.file).path) != key) continue;
            const SourceFile& file = sources.file(d.loc.file);
            const json j = cli::diagnosticJson(d, sources);
            const int line = j["line"].get<int>(), col = j["column"].get<int>();
            const int endLine = j["end"]["line"].get<int>(), endCol = j["end"]["column"].get<int>();
            const std::string_view text = lineOf(file.shownText(), line);
            const std::string_view endText = endLine == line ? text : lineOf(file.shownText(), endLine);
            json out = {
                {"range", {{"start", {{"line", line - 1}, {"character", characterOfColumn(text, col)}}},
                           {"end", {{"line", endLine - 1}, {"character", characterOfColumn(endText, endCol)}}}}},
                {"severity", d.severity == Severity::Error ? 1 : 2},
                {"source", "strun"},
                {"message", d.message},
            };
            if (!d.code.empty()) out["code"] = d.code;
            json related = json::array();
            for (const DiagnosticNote& n : d.notes) {
                ast::Loc at = n.loc ? *n.loc : d.loc;
                if (at.file < 0 || at.file >= sources.size()) at = d.loc;
                related.push_back({{"location", {{"uri", uriOfFile(*current_, at.file)}, {"range", rangeOf(*current_, at, 1)}}},
                                   {"message", n.text}});
            }
            for (const std::string& h : d.help)
                related.push_back({{"location", {{"uri", doc.uri}, {"range", out["range"]}}}, {"message", "help: " + h}});
            if (!related.empty()) out["relatedInformation"] = std::move(related);
            list.push_back(std::move(out));
        }
        notify("textDocument/publishDiagnostics", {{"uri", doc.uri}, {"version", doc.version}, {"diagnostics", std::move(list)}});
    }
}

// The previous compile is freed on a thread of its own: the next request is
// answered meanwhile (freeing a large project's model and AST takes a sixth
// of compiling it).
void LspServer::retire() {
    if (!retired_) return;
    std::thread([old = std::move(retired_)]() mutable { old.reset(); }).detach();
}

void LspServer::publishEmpty(const std::string& uri) {
    notify("textDocument/publishDiagnostics", {{"uri", uri}, {"diagnostics", json::array()}});
}

// ---------------------------------------------------------------- positions

int LspServer::fileOfPath(const ProjectIndex& index, const std::string& key) const {
    for (int f : index.userFiles())
        if (normalPath(index.sources().file(f).path) == key) return f;
    return -1;
}

std::string LspServer::uriOfFile(const ProjectIndex& index, int file) const {
    if (file < 0 || file >= index.sources().size()) return "";
    const std::string key = normalPath(index.sources().file(file).path);
    auto it = documents_.find(key);
    return it != documents_.end() ? it->second.uri : uriOfPath(key);
}

bool LspServer::locate(const ProjectIndex& index, const json& params, Where& where) const {
    const std::string key = normalPath(pathOfUri(params.at("textDocument").at("uri").get<std::string>()));
    where.file = fileOfPath(index, key);
    if (where.file < 0) return false;
    const json& pos = params.at("position");
    where.userLine = pos.at("line").get<int>() + 1;
    const SourceFile& file = index.sources().file(where.file);
    where.userCol = columnOfCharacter(lineOf(file.shownText(), where.userLine), pos.at("character").get<int>());
    std::tie(where.line, where.col) = index.compiledPosition(where.file, where.userLine, where.userCol);
    return where.line > 0;
}

json LspServer::rangeOf(const ProjectIndex& index, const ast::Loc& loc, int length) const {
    const SourceFile& file = index.sources().file(loc.file);
    auto [line, col] = file.original(loc.line, loc.col);
    line = std::max(line, 1);
    col = std::max(col, 1);
    const std::string_view text = lineOf(file.shownText(), line);
    return {{"start", {{"line", line - 1}, {"character", characterOfColumn(text, col)}}},
            {"end", {{"line", line - 1}, {"character", characterOfColumn(text, col + length)}}}};
}

json LspServer::locationOf(const ProjectIndex& index, int symbol) const {
    const Symbol& s = index.symbols()[static_cast<size_t>(symbol)];
    return {{"uri", uriOfFile(index, s.loc.file)}, {"range", rangeOf(index, s.loc, codePoints(s.name))}};
}

// ---------------------------------------------------------------- requests

json LspServer::hover(const json& params) {
    if (!current_) return nullptr;
    const ProjectIndex& index = *current_;
    Where w;
    if (!locate(index, params, w)) return nullptr;
    const Occurrence* o = index.occurrenceAt(w.file, w.line, w.col);
    if (!o) return nullptr;
    const Symbol& s = index.symbols()[static_cast<size_t>(o->symbol)];
    std::string code, where;
    const SourceFile& declFile = index.sources().file(s.loc.file);
    const int declLine = declFile.original(s.loc.line, s.loc.col).first;
    const std::string fileName = fs::path(declFile.path).filename().string();
    switch (s.kind) {
        case SymbolKind::Variable:
        case SymbolKind::Field: {
            code = s.name + " : " + s.detail;
            std::string owner;
            if (s.parent >= 0) {
                const Symbol& p = index.symbols()[static_cast<size_t>(s.parent)];
                owner = p.kind == SymbolKind::GlobalList || p.kind == SymbolKind::Configuration ? std::string(" in ") + p.name
                                                                                               : std::string(" of ") + p.name;
            }
            where = std::string(s.kind == SymbolKind::Field ? "member" : kindWord(s)) + owner + ", declared at " + fileName + ":" +
                    std::to_string(declLine);
            break;
        }
        default:
            code = s.detail;
            where = "declared at " + fileName + ":" + std::to_string(declLine);
            break;
    }
    const std::string value = "```st\n" + code + "\n```\n" + where;
    return {{"contents", {{"kind", "markdown"}, {"value", value}}},
            {"range", rangeOf(index, ast::Loc{w.file, o->line, o->col}, o->length)}};
}

json LspServer::definition(const json& params) {
    if (!current_) return nullptr;
    Where w;
    if (!locate(*current_, params, w)) return nullptr;
    const Occurrence* o = current_->occurrenceAt(w.file, w.line, w.col);
    if (!o) return nullptr;
    const Symbol& s = current_->symbols()[static_cast<size_t>(o->symbol)];
    const auto& users = current_->userFiles();
    if (std::find(users.begin(), users.end(), s.loc.file) == users.end()) return nullptr;  // strun's own library
    return locationOf(*current_, o->symbol);
}

json LspServer::references(const json& params) {
    json out = json::array();
    if (!current_) return out;
    Where w;
    if (!locate(*current_, params, w)) return out;
    const Occurrence* o = current_->occurrenceAt(w.file, w.line, w.col);
    if (!o) return out;
    bool withDeclaration = true;
    if (params.contains("context") && params["context"].is_object())
        withDeclaration = params["context"].value("includeDeclaration", true);
    for (const auto& [file, occ] : current_->occurrencesOf(o->symbol)) {
        if (occ.declaration && !withDeclaration) continue;
        out.push_back({{"uri", uriOfFile(*current_, file)}, {"range", rangeOf(*current_, ast::Loc{file, occ.line, occ.col}, occ.length)}});
    }
    return out;
}

json LspServer::documentSymbol(const json& params) {
    json out = json::array();
    if (!current_) return out;
    const ProjectIndex& index = *current_;
    const int file = fileOfPath(index, normalPath(pathOfUri(params.at("textDocument").at("uri").get<std::string>())));
    if (file < 0) return out;
    const SourceFile& source = index.sources().file(file);
    auto symbolJson = [&](int id) {
        const Symbol& s = index.symbols()[static_cast<size_t>(id)];
        json selection = rangeOf(index, s.loc, codePoints(s.name));
        json range = rangeOf(index, s.start, 0);
        const int endLine = source.original(s.end.line, s.end.col).first;
        range["end"] = {{"line", endLine - 1}, {"character", characterOfColumn(lineOf(source.shownText(), endLine), 1 << 20)}};
        auto before = [](const json& a, const json& b) {
            return a["line"].get<int>() < b["line"].get<int>() ||
                   (a["line"].get<int>() == b["line"].get<int>() && a["character"].get<int>() < b["character"].get<int>());
        };
        if (before(selection["start"], range["start"])) range["start"] = selection["start"];
        if (before(range["end"], selection["end"])) range["end"] = selection["end"];
        return json{{"name", s.name}, {"detail", s.detail}, {"kind", symbolKindNumber(s.kind)}, {"range", range},
                    {"selectionRange", selection}, {"children", json::array()}};
    };
    const auto& symbols = index.symbols();
    for (size_t k = 0; k < symbols.size(); ++k) {
        const Symbol& s = symbols[k];
        if (s.parent >= 0 || s.loc.file != file || s.kind == SymbolKind::Variable) continue;
        json item = symbolJson(static_cast<int>(k));
        if (s.pou)
            for (size_t c = 0; c < symbols.size(); ++c) {
                const Symbol& child = symbols[c];
                if (child.parent == static_cast<int>(k) &&
                    (child.kind == SymbolKind::Method || child.kind == SymbolKind::Action || child.kind == SymbolKind::Property))
                    item["children"].push_back(symbolJson(static_cast<int>(c)));
            }
        out.push_back(std::move(item));
    }
    return out;
}

json LspServer::completion(const json& params) {
    json items = json::array();
    const std::string key = normalPath(pathOfUri(params.at("textDocument").at("uri").get<std::string>()));
    const int line0 = params.at("position").at("line").get<int>();
    const int character = params.at("position").at("character").get<int>();
    std::string text = documentText(key);
    std::shared_ptr<ProjectIndex> index = lastChecked_ ? lastChecked_ : current_;
    if (!index) return {{"isIncomplete", false}, {"items", items}};
    const int file = fileOfPath(*index, key);
    if (text.empty() && file >= 0) text = index->sources().file(file).shownText();
    const std::string_view lineText = lineOf(text, line0 + 1);
    const size_t cursor = byteOfColumn(lineText, columnOfCharacter(lineText, character));
    size_t wordStart = cursor;
    while (wordStart > 0 && isWordChar(lineText[wordStart - 1])) --wordStart;
    int cline = line0 + 1;
    if (file >= 0) cline = index->compiledPosition(file, line0 + 1, 1).first;
    auto addSymbol = [&](int id) {
        const Symbol& s = index->symbols()[static_cast<size_t>(id)];
        items.push_back({{"label", s.name}, {"kind", completionKindNumber(s.kind)}, {"detail", s.detail}});
    };
    if (wordStart > 0 && lineText[wordStart - 1] == '.') {
        const std::vector<std::string> chain = chainBefore(lineText, wordStart - 1);
        if (!chain.empty() && file >= 0)
            for (int id : index->membersOfChain(file, cline, chain)) addSymbol(id);
        return {{"isIncomplete", false}, {"items", items}};
    }
    if (file >= 0)
        for (int id : index->visibleAt(file, cline)) addSymbol(id);
    for (const char* k : kKeywords) items.push_back({{"label", k}, {"kind", 14}});
    return {{"isIncomplete", false}, {"items", items}};
}

json LspServer::signatureHelp(const json& params) {
    const std::string key = normalPath(pathOfUri(params.at("textDocument").at("uri").get<std::string>()));
    const int line0 = params.at("position").at("line").get<int>();
    const int character = params.at("position").at("character").get<int>();
    std::shared_ptr<ProjectIndex> index = lastChecked_ ? lastChecked_ : current_;
    if (!index) return nullptr;
    const int file = fileOfPath(*index, key);
    if (file < 0) return nullptr;
    std::string text = documentText(key);
    if (text.empty()) text = index->sources().file(file).shownText();
    // The cursor as a byte offset in the whole text.
    size_t offset = 0;
    for (int l = 0; l < line0; ++l) {
        const size_t nl = text.find('\n', offset);
        if (nl == std::string::npos) return nullptr;
        offset = nl + 1;
    }
    {
        size_t end = text.find('\n', offset);
        if (end == std::string::npos) end = text.size();
        const std::string_view lineText(text.data() + offset, end - offset);
        offset += byteOfColumn(lineText, columnOfCharacter(lineText, character));
    }
    // Back to the unmatched '(' (at most a few thousand characters back),
    // counting the commas of this call and noting a named argument's name.
    int depth = 0, commas = 0;
    size_t open = std::string::npos;
    std::string namedArg;
    size_t lastArgStart = offset;
    const size_t limit = offset > 4000 ? offset - 4000 : 0;
    for (size_t i = offset; i > limit; --i) {
        const char c = text[i - 1];
        if (c == ')' || c == ']') ++depth;
        else if (c == '(' || c == '[') {
            if (depth == 0) {
                if (c == '[') return nullptr;
                open = i - 1;
                break;
            }
            --depth;
        } else if (c == ',' && depth == 0) {
            if (commas == 0) lastArgStart = i;
            ++commas;
        } else if (c == ';') {
            return nullptr;
        }
    }
    if (open == std::string::npos) return nullptr;
    if (commas == 0) lastArgStart = open + 1;
    {
        // `name :=` or `name =>` at the start of the current argument.
        std::string_view arg(text.data() + lastArgStart, offset - lastArgStart);
        size_t k = 0;
        while (k < arg.size() && std::isspace(static_cast<unsigned char>(arg[k]))) ++k;
        size_t nameEnd = k;
        while (nameEnd < arg.size() && isWordChar(arg[nameEnd])) ++nameEnd;
        size_t op = nameEnd;
        while (op < arg.size() && std::isspace(static_cast<unsigned char>(arg[op]))) ++op;
        if (nameEnd > k && (arg.substr(op, 2) == ":=" || arg.substr(op, 2) == "=>")) namedArg = sema::upper(std::string(arg.substr(k, nameEnd - k)));
    }
    size_t before = open;
    while (before > 0 && (text[before - 1] == ' ' || text[before - 1] == '\t')) --before;
    const std::vector<std::string> chain = chainBefore(text, before);
    if (chain.empty()) return nullptr;
    // The line of the call, for the scope of its names.
    int callLine = 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(open), '\n'));
    const int cline = index->compiledPosition(file, callLine, 1).first;
    const int callee = index->calleeOfChain(file, cline > 0 ? cline : callLine, chain);
    if (callee < 0) return nullptr;
    const Symbol& s = index->symbols()[static_cast<size_t>(callee)];
    std::string label = s.name + "(";
    json parameters = json::array();
    int active = commas;
    for (size_t k = 0; k < s.params.size(); ++k) {
        if (k) label += ", ";
        parameters.push_back({{"label", s.params[k]}});
        label += s.params[k];
        if (!namedArg.empty()) {
            std::string p = s.params[k];
            const size_t colon = p.find(" : ");
            std::string pname = p.substr(0, colon);
            if (const size_t sp = pname.rfind(' '); sp != std::string::npos) pname = pname.substr(sp + 1);
            if (sema::upper(pname) == namedArg) active = static_cast<int>(k);
        }
    }
    label += ")";
    if (s.pou && s.pou->returnType) label += s.detail.substr(s.detail.rfind(" : "));
    json signature = {{"label", label}, {"documentation", s.detail}, {"parameters", parameters}};
    if (!s.params.empty()) active = std::min(active, static_cast<int>(s.params.size()) - 1);
    signature["activeParameter"] = active;
    return {{"signatures", json::array({signature})}, {"activeSignature", 0}, {"activeParameter", active}};
}

// ---------------------------------------------------------------- output

void LspServer::reply(const json& id, json result) { writer_.send({{"jsonrpc", "2.0"}, {"id", id}, {"result", std::move(result)}}); }

void LspServer::replyError(const json& id, int code, const std::string& message) {
    writer_.send({{"jsonrpc", "2.0"}, {"id", id}, {"error", {{"code", code}, {"message", message}}}});
}

void LspServer::notify(const std::string& method, json params) {
    writer_.send({{"jsonrpc", "2.0"}, {"method", method}, {"params", std::move(params)}});
}

}  // namespace strun::editors::lsp
