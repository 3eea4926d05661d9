// The IEC 61131-3 character-string functions LEN LEFT RIGHT MID CONCAT INSERT
// DELETE REPLACE FIND for STRING (std::string, one byte per character) and
// WSTRING (std::u16string, one UTF-16 code unit per character). Positions are
// 1-based like in ST. Out-of-range arguments never fail: they follow the
// CODESYS Standard library where it documents a behaviour and decision 0033
// elsewhere:
//   LEFT/RIGHT(s, n)     n <= 0 -> ''; n >= LEN(s) -> s
//   MID(s, L, P)         L <= 0, P < 1 or P > LEN(s) -> ''; otherwise up to L characters from P
//   INSERT(s1, s2, P)    P < 0 -> s1; P = 0 inserts before the first character;
//                        P >= LEN(s1) appends
//   DELETE(s, L, P)      P < 0, L <= 0 or P > LEN(s) -> s; P = 0 works like P = 1 with
//                        L - 1 (the documented CODESYS quirk); deletes up to the end at most
//   REPLACE(s1, s2, L, P) P < 0 -> s1; P = 0 works like P = 1 with L - 1 (CODESYS quirk);
//                        L < 0 counts as 0; P > LEN(s1) + 1 appends s2
//   FIND(s1, s2)         first position of s2 in s1, 0 when absent or when s2 is empty
// Results are not cut to any length here; truncateToLength applies a
// declared STRING[n] / WSTRING[n] length when the result is stored.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

namespace strun::stdlib {

int64_t stringLength(std::string_view s);
int64_t stringLength(std::u16string_view s);

std::string stringLeft(std::string_view s, int64_t size);
std::u16string stringLeft(std::u16string_view s, int64_t size);

std::string stringRight(std::string_view s, int64_t size);
std::u16string stringRight(std::u16string_view s, int64_t size);

std::string stringMid(std::string_view s, int64_t length, int64_t position);
std::u16string stringMid(std::u16string_view s, int64_t length, int64_t position);

std::string stringConcat(std::string_view first, std::string_view second);
std::u16string stringConcat(std::u16string_view first, std::u16string_view second);

std::string stringInsert(std::string_view s1, std::string_view s2, int64_t position);
std::u16string stringInsert(std::u16string_view s1, std::u16string_view s2, int64_t position);

std::string stringDelete(std::string_view s, int64_t length, int64_t position);
std::u16string stringDelete(std::u16string_view s, int64_t length, int64_t position);

std::string stringReplace(std::string_view s1, std::string_view s2, int64_t length,
                          int64_t position);
std::u16string stringReplace(std::u16string_view s1, std::u16string_view s2, int64_t length,
                             int64_t position);

int64_t stringFind(std::string_view s1, std::string_view s2);
int64_t stringFind(std::u16string_view s1, std::u16string_view s2);

// The first maxLength characters ('' when maxLength <= 0): what a variable
// declared STRING[maxLength] keeps of an assigned value.
std::string truncateToLength(std::string_view s, int64_t maxLength);
std::u16string truncateToLength(std::u16string_view s, int64_t maxLength);

// Declared-length limits of STRING / WSTRING. TwinCAT sets no limit
// (`STRING(100000)` in LCLS's JSON reader); strun's is 1 Mi characters
// (decision 0437, docs/limits.md): a STRING of it is 1 MiB of its
// instance, a WSTRING 2 MiB.
inline constexpr int64_t kDefaultStringLength = 80;
inline constexpr int64_t kMaxStringLength = 1 << 20;

}  // namespace strun::stdlib
