# Writes OUTPUT, a C++ source defining affinterp::plots::viewer_page as the text of INPUT (the viewer page),
# so the page is edited as HTML and shipped inside the library.
file(READ "${INPUT}" page)
string(FIND "${page}" ")affinterp_page\"" clash)
if(NOT clash EQUAL -1)
  message(FATAL_ERROR "${INPUT} contains the raw-string delimiter )affinterp_page\"")
endif()
string(FIND "${page}" "@AFFINTERP_DATA@" marker)
if(marker EQUAL -1)
  message(FATAL_ERROR "${INPUT} lacks the data marker @AFFINTERP_DATA@")
endif()
file(WRITE "${OUTPUT}.tmp" "// Generated from plots/viewer/viewer.html by plots/viewer/embed.cmake: edit the page, not this.
#include <string_view>
namespace affinterp::plots {
extern const std::string_view viewer_page;
const std::string_view viewer_page = R\"affinterp_page(${page})affinterp_page\";
}  // namespace affinterp::plots
")
file(COPY_FILE "${OUTPUT}.tmp" "${OUTPUT}" ONLY_IF_DIFFERENT)
file(REMOVE "${OUTPUT}.tmp")
