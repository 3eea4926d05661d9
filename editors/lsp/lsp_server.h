// strun lsp: a Language Server Protocol 3.17 server on stdin / stdout
// (docs/editors.md). The project is every source under the workspace folder
// with the open documents in their edited state; after each change the
// project is checked again, with only the changed files parsed again
// (parse_cache.h; figures in docs/editors.md), and the diagnostics of every
// open document are published.
#pragma once

#include <condition_variable>
#include <cstdio>
#include <deque>
#include <map>
#include <memory>
#include <mutex>
#include <string>

#include <nlohmann/json.hpp>

#include "editors/lsp/parse_cache.h"
#include "editors/lsp/project_index.h"
#include "interpreter/project/compile.h"
#include "editors/protocol/message_stream.h"
#include "interpreter/sema/compile_options.h"

namespace strun::editors::lsp {

class LspServer {
public:
    LspServer(std::FILE* in, std::FILE* out);
    // Serves until `exit` or the end of the input; returns the exit status.
    int run();

private:
    struct Document {
        std::string uri;  // as the client wrote it (answers use the same text)
        std::string text;
        int64_t version = 0;
    };
    using json = nlohmann::json;

    void readLoop();
    void handle(const json& message);
    json dispatch(const std::string& method, const json& params, bool& isNotification);
    json initialize(const json& params);
    void didOpen(const json& params);
    void didChange(const json& params);
    void didClose(const json& params);
    json hover(const json& params);
    json definition(const json& params);
    json references(const json& params);
    json documentSymbol(const json& params);
    json completion(const json& params);
    json signatureHelp(const json& params);

    void recompile();
    void publishDiagnostics();
    void publishEmpty(const std::string& uri);
    void retire();
    void reply(const json& id, json result);
    void replyError(const json& id, int code, const std::string& message);
    void notify(const std::string& method, json params);

    // A request's document and position resolved in `index`: the file index
    // and the compiled-text position; false when the document is not part of it.
    struct Where {
        int file = -1;
        int line = 0, col = 0;          // compiled text
        int userLine = 0, userCol = 0;  // the file as the user has it
    };
    bool locate(const ProjectIndex& index, const json& params, Where& where) const;
    int fileOfPath(const ProjectIndex& index, const std::string& key) const;
    std::string uriOfFile(const ProjectIndex& index, int file) const;
    json rangeOf(const ProjectIndex& index, const ast::Loc& loc, int length) const;
    json locationOf(const ProjectIndex& index, int symbol) const;
    std::string documentText(const std::string& key) const;

    MessageReader reader_;
    MessageWriter writer_;
    std::mutex queueMutex_;
    std::condition_variable queueReady_;
    std::deque<Incoming> queue_;
    bool inputEnded_ = false;

    bool initialized_ = false;
    bool shutdown_ = false;
    bool exitRequested_ = false;
    bool dirty_ = false;
    std::string root_;  // workspace folder ("" : only the open documents)
    sema::CompileOptions options_;
    std::map<std::string, Document> documents_;  // by normalised path
    // The last compile the checker ran through (a half-typed `x.` stops the
    // parser): completion and signature help read it while the text is broken.
    std::shared_ptr<ProjectIndex> lastChecked_;
    std::unique_ptr<project::ParsedLibrary> library_;  // lent to every compile
    ParseCache parsed_;                                 // the user's files as last parsed
    std::shared_ptr<ProjectIndex> current_;
    std::shared_ptr<ProjectIndex> retired_;
};

}  // namespace strun::editors::lsp
