// The base protocol LSP and DAP share: messages framed by a
// `Content-Length: N` header block and N bytes of JSON, on a byte stream
// (stdin / stdout). Reading is bounded and never gives up on the stream: a
// header block without a length, a line too long, a body that is not JSON or
// is larger than kMaxMessageBytes is reported as a bad message and the
// reader goes on with what follows; only the end of the input ends it.
#pragma once

#include <cstddef>
#include <cstdio>
#include <mutex>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

namespace strun::editors {

inline constexpr std::size_t kMaxMessageBytes = std::size_t{64} << 20;  // a 4 MiB source escaped, with room
inline constexpr std::size_t kMaxHeaderLineBytes = 8192;

// One framed message as read: either JSON or the reason it is not.
struct Incoming {
    std::optional<nlohmann::json> message;  // set when the body parsed as a JSON object
    std::string error;                      // otherwise: why (for the protocol's parse-error answer)
};

class MessageReader {
public:
    explicit MessageReader(std::FILE* in) : in_(in) {}
    // The next message; false at the end of the input.
    bool next(Incoming& out);

private:
    int get();
    bool readLine(std::string& line, bool& tooLong);
    std::FILE* in_;
    // Bytes to read again: the start of a message found inside a broken one
    // (a half message followed by a whole one resynchronises on the latter).
    std::string pending_;
    size_t pendingAt_ = 0;
};

// Writes framed messages; safe to call from several threads (the debugger's
// run thread sends events while the request thread answers).
class MessageWriter {
public:
    explicit MessageWriter(std::FILE* out) : out_(out) {}
    void send(const nlohmann::json& message);

private:
    std::FILE* out_;
    std::mutex mutex_;
};

}  // namespace strun::editors
