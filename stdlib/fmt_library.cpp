// fmt's compiled part, built once here instead of in every file that formats
// (decision 0260). Debian's libfmt-dev ships fmt only as headers and a shared
// library; strun links its C++ libraries statically (decision 0156), and a
// shared libfmt would bring the shared libstdc++ back in with it. Every other
// file includes <fmt/format.h> without FMT_HEADER_ONLY and so only declares
// what this file defines: the non-template functions of format-inl.h and the
// template instances format.h declares extern.
#include <fmt/format-inl.h>

FMT_BEGIN_NAMESPACE
namespace detail {

template auto dragonbox::to_decimal<float>(float x) noexcept -> dragonbox::decimal_fp<float>;
template auto dragonbox::to_decimal<double>(double x) noexcept -> dragonbox::decimal_fp<double>;
template auto thousands_sep_impl<char>(locale_ref) -> thousands_sep_result<char>;
template auto decimal_point_impl<char>(locale_ref) -> char;
template void vformat_to<char>(buffer<char>&, basic_string_view<char>, basic_format_args<buffer_context<char>>, locale_ref);

}  // namespace detail
FMT_END_NAMESPACE
