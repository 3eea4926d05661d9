#include <string_view>

#include "interpreter/builtins/libraries/library_natives.h"
#include "interpreter/builtins/register_builtins.h"

namespace strun::stdlib {

void registerLibraryBuiltins(sema::Checker& checker, const std::vector<std::string_view>& libraries) {
    for (std::string_view library : libraries) {
        if (library == "Tc2_System") bind::registerTc2SystemNatives(checker);
        else if (library == "Tc2_EtherCAT") bind::registerTc2EtherCatNatives(checker);
        else if (library == "Tc2_Utilities") bind::registerTc2UtilitiesNatives(checker);
        else if (library == "Tc2_MC2") bind::registerTc2Mc2Natives(checker);
        else if (library == "Tc3_JsonXml") bind::registerTc3JsonXmlNatives(checker);
    }
}

}  // namespace strun::stdlib
