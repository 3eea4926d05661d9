// The input stage in front of the parser: the FILE and DIR arguments of a
// command line become the sources of one project. ST files are read as they
// are; TwinCAT objects and PLCopen XML projects are converted to ST that
// keeps the XML positions (xml_inputs.h).
#pragma once

#include <string>
#include <vector>

#include "interpreter/source/source_set.h"

namespace strun::source {

// A TwinCAT 3 object file (.TcPOU, .TcDUT, .TcGVL, .TcIO, .TcTTO, .TcTLEO), by extension.
bool isTwinCatObject(const std::string& path);

// What a directory contributes: ST, PLCopen XML and TwinCAT objects, by extension.
bool isProjectSource(const std::string& path);

// One source given as text (an editor's open document): converted by its
// extension as a file of that name would be.
void addProjectSourceText(const std::string& path, std::string text, SourceSet& sources, std::vector<int>& userFiles, CompileLog& log);

// Reads every FILE (a FILE of any other extension is ST; `-` is ST read from
// standard input, named <stdin> in messages, at most once) and every source
// file under a DIR, recursively, in name order. Returns false with
// `usageError` set when a path does not exist, cannot be read, or is a
// directory without any source. Errors in the files themselves (XML that is
// not well-formed, a body in FBD) go to `log`.
bool readProjectInputs(const std::vector<std::string>& paths, SourceSet& sources, std::vector<int>& userFiles, CompileLog& log,
                       std::string& usageError);

}  // namespace strun::source
