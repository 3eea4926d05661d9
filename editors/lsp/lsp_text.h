// Text positions and file names as the Language Server Protocol has them
// (0-based lines, UTF-16 code units, file:// URIs) against strun's (1-based
// lines, columns counted in code points, paths).
#pragma once

#include <string>
#include <string_view>

namespace strun::editors::lsp {

// file:///a%20b/c.st -> /a b/c.st; "" when `uri` is not a file URI.
std::string pathOfUri(std::string_view uri);
// /a b/c.st -> file:///a%20b/c.st
std::string uriOfPath(std::string_view path);

// Line `line` (1-based) of `text` without its line end ("" past the end).
std::string_view lineOf(std::string_view text, int line);
// 1-based code-point column of the UTF-16 offset `character` in `lineText`.
int columnOfCharacter(std::string_view lineText, int character);
// UTF-16 offset of the 1-based code-point column `col` in `lineText`.
int characterOfColumn(std::string_view lineText, int col);
// Byte offset of the 1-based code-point column `col` in `lineText`.
size_t byteOfColumn(std::string_view lineText, int col);

}  // namespace strun::editors::lsp
