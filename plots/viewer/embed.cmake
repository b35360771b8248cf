# Writes OUTPUT, a C++ source defining affinterp::plots::NAME (viewer_page unless -DNAME=... says otherwise) as
# the text of INPUT (a viewer page), so the page is edited as HTML and shipped inside the library.
if(NOT DEFINED NAME)
  set(NAME viewer_page)
endif()
file(READ "${INPUT}" page)
string(FIND "${page}" ")affinterp_page\"" clash)
if(NOT clash EQUAL -1)
  message(FATAL_ERROR "${INPUT} contains the raw-string delimiter )affinterp_page\"")
endif()
string(FIND "${page}" "@AFFINTERP_DATA@" marker)
if(marker EQUAL -1)
  message(FATAL_ERROR "${INPUT} lacks the data marker @AFFINTERP_DATA@")
endif()
get_filename_component(page_name "${INPUT}" NAME)
file(WRITE "${OUTPUT}.tmp" "// Generated from plots/viewer/${page_name} by plots/viewer/embed.cmake: edit the page, not this.
#include <string_view>
namespace affinterp::plots {
extern const std::string_view ${NAME};
const std::string_view ${NAME} = R\"affinterp_page(${page})affinterp_page\";
}  // namespace affinterp::plots
")
file(COPY_FILE "${OUTPUT}.tmp" "${OUTPUT}" ONLY_IF_DIFFERENT)
file(REMOVE "${OUTPUT}.tmp")
