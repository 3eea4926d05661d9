// The monitor page of --serve: live/web/index.html with live/web/monitor.css
// and live/web/monitor.js put inline, embedded into the binary at build time
// (live/web/embed_web.cmake), so the page loads nothing from anywhere else.
#pragma once

#include <string_view>

namespace strun::live {

std::string_view monitorPage();

}  // namespace strun::live
