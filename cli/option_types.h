// The value types of strun's options as CLI11 validators: each trims
// surrounding whitespace, checks the text, and names its type in --help
// (DURATION, N, FILE, DT, NAME) instead of CLI11's TEXT.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "cli/cli11_fwd.h"

namespace strun::cli {

// An IEC duration (`T#1s500ms`, `TIME#20ms`), a bare one (`150ms`) or a bare
// `0`. Nanoseconds, or nullopt with `error` set.
std::optional<int64_t> parseDuration(std::string_view text, std::string& error);
// The nanoseconds of a text that already passed durationValidator().
int64_t validatedDuration(const std::string& text);

// Validators (they rewrite the option's text to its trimmed form).
CLI::Validator durationValidator();       // DURATION, >= 0
CLI::Validator positiveCountValidator();  // N >= 1
CLI::Validator dateTimeValidator();       // DT#2026-01-31-13:05:00
CLI::Validator readableFileValidator(bool allowStdin = false);  // an existing, readable regular file (or directory; `-` if allowStdin)

std::string trimmed(std::string_view text);

}  // namespace strun::cli
