// The native functions of the vendor libraries (stdlib/libraries/<Library>),
// one registration per library, called only for the libraries a project
// names (interpreter/project/library_selection.h, decision 0220). The names
// each registers are listed as `native:` in the library's library.txt.
#pragma once

#include "interpreter/builtins/bind_support.h"

namespace strun::stdlib::bind {

void registerTc2SystemNatives(sema::Checker& ck);      // ADSLOG*, F_GetTaskTime, F_GetSystemTime, GETCURTASKINDEXEX, files
void registerTc2SystemFileNatives(sema::Checker& ck);  // F_strun_File*: the FB_File* blocks' work in the --files sandbox
void registerTc2EtherCatNatives(sema::Checker& ck);    // DC time
void registerTc2UtilitiesNatives(sema::Checker& ck);   // F_strun_FormatArg
void registerTc2Mc2Natives(sema::Checker& ck);         // F_strun_TaskStartNanos: the simulated axes' clock
void registerTc3JsonXmlNatives(sema::Checker& ck);     // F_strun_Json, F_strun_JsonReal: the DOM parser and SAX reader
void registerTc3JsonSymbolNatives(sema::Checker& ck);  // F_strun_JsonSymbol: FB_JsonReadWriteDataType

}  // namespace strun::stdlib::bind
