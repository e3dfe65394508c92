# cmake -DINPUT=page.html -DOUTPUT=viewer_page.cpp -P embed_page.cmake: the page as a C++ raw
# string, so the viewer serves it without files beside the binary and without a page build step.
file(READ "${INPUT}" page)
string(FIND "${page}" ")viewerpage\"" clash)
if(NOT clash EQUAL -1)
  message(FATAL_ERROR "${INPUT} contains the raw string's end marker )viewerpage\"")
endif()
file(WRITE "${OUTPUT}.tmp"
  "// Generated from services/viewer/web/page.html by embed_page.cmake: do not edit.\n"
  "#include \"services/viewer/web/page.hpp\"\n\n"
  "namespace autonomy::viewer {\n\n"
  "std::string_view viewer_page_html() {\n"
  "  static constexpr char kPage[] = R\"viewerpage(${page})viewerpage\";\n"
  "  return {kPage, sizeof(kPage) - 1};\n"
  "}\n\n"
  "}  // namespace autonomy::viewer\n")
file(COPY_FILE "${OUTPUT}.tmp" "${OUTPUT}" ONLY_IF_DIFFERENT)
file(REMOVE "${OUTPUT}.tmp")
