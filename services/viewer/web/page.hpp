#pragma once
// The viewer's single page (web/page.html: HTML, CSS and plain JavaScript drawing on a canvas,
// nothing fetched from elsewhere), embedded into the binary at build time (embed_page.cmake).
#include <string_view>

namespace autonomy::viewer {

std::string_view viewer_page_html();

}  // namespace autonomy::viewer
