#include "editors/protocol/message_stream.h"

#include <cctype>
#include <charconv>
#include <string_view>

namespace strun::editors {

int MessageReader::get() {
    if (pendingAt_ < pending_.size()) return static_cast<unsigned char>(pending_[pendingAt_++]);
    if (!pending_.empty()) {
        pending_.clear();
        pendingAt_ = 0;
    }
    return getc_unlocked(in_);
}

// One header line without its CR LF. A line longer than kMaxHeaderLineBytes
// is consumed to its end and flagged.
bool MessageReader::readLine(std::string& line, bool& tooLong) {
    line.clear();
    tooLong = false;
    for (;;) {
        int c = get();
        if (c == EOF) return !line.empty() || tooLong;
        if (c == '\n') {
            if (!line.empty() && line.back() == '\r') line.pop_back();
            return true;
        }
        if (line.size() < kMaxHeaderLineBytes) line.push_back(static_cast<char>(c));
        else tooLong = true;
    }
}

namespace {

bool equalsNoCase(std::string_view a, std::string_view b) {
    if (a.size() != b.size()) return false;
    for (size_t i = 0; i < a.size(); ++i)
        if (std::tolower(static_cast<unsigned char>(a[i])) != std::tolower(static_cast<unsigned char>(b[i]))) return false;
    return true;
}

std::string_view trim(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
    return s;
}

}  // namespace

bool MessageReader::next(Incoming& out) {
    out.message.reset();
    out.error.clear();
    std::string line;
    bool tooLong = false;
    bool sawHeader = false;
    bool badHeader = false;
    std::optional<std::size_t> length;
    // The header block: lines up to an empty one.
    for (;;) {
        if (!readLine(line, tooLong)) return false;
        if (tooLong) { badHeader = true; sawHeader = true; continue; }
        if (line.empty()) {
            if (!sawHeader) continue;  // blank lines between messages
            break;
        }
        sawHeader = true;
        // Garbage without a line end before a header: the header is what counts.
        if (const size_t at = line.find("Content-Length:"); at != std::string::npos && at > 0) line.erase(0, at);
        const auto colon = line.find(':');
        if (colon == std::string::npos) { badHeader = true; continue; }
        std::string_view name = trim(std::string_view(line).substr(0, colon));
        std::string_view value = trim(std::string_view(line).substr(colon + 1));
        if (equalsNoCase(name, "Content-Length")) {
            std::size_t n = 0;
            auto [end, ec] = std::from_chars(value.data(), value.data() + value.size(), n);
            if (ec != std::errc() || end != value.data() + value.size()) badHeader = true;
            else length = n;
        }
    }
    if (!length) {
        out.error = badHeader ? "malformed header (no valid Content-Length)" : "missing Content-Length header";
        return true;
    }
    if (*length > kMaxMessageBytes) {
        // Skipped unread: the stream stays framed.
        for (std::size_t k = 0; k < *length; ++k)
            if (get() == EOF) return false;
        out.error = "message of " + std::to_string(*length) + " bytes is larger than the limit of " + std::to_string(kMaxMessageBytes);
        return true;
    }
    std::string body(*length, '\0');
    for (std::size_t k = 0; k < *length; ++k) {
        const int c = get();
        if (c == EOF) return false;  // the input ended inside the body
        body[k] = static_cast<char>(c);
    }
    nlohmann::json parsed = nlohmann::json::parse(body, nullptr, false);
    if (parsed.is_discarded()) {
        out.error = "the message body is not valid JSON";
        // A shorter message than its header said, followed by the next one:
        // read again from that one's header.
        if (const size_t at = body.find("Content-Length:"); at != std::string::npos && at > 0) {
            pending_ = body.substr(at) + pending_.substr(std::min(pendingAt_, pending_.size()));
            pendingAt_ = 0;
        }
        return true;
    }
    if (!parsed.is_object()) {
        out.error = "the message is not a JSON object";
        return true;
    }
    out.message = std::move(parsed);
    return true;
}

void MessageWriter::send(const nlohmann::json& message) {
    // Invalid UTF-8 in a value (a source file's bytes) is replaced, never thrown.
    const std::string body = message.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
    std::lock_guard<std::mutex> lock(mutex_);
    std::fprintf(out_, "Content-Length: %zu\r\n\r\n", body.size());
    std::fwrite(body.data(), 1, body.size(), out_);
    std::fflush(out_);
}

}  // namespace strun::editors
