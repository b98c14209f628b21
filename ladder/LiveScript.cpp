// The live part of the ladder page (docs/ladder-view.md "Live view"): the script and style in
// ladder/web/, embedded into the binary at build time (ladder/web/embed.cmake makes
// WebAssets.cpp from the files) and appended to renderHtml's page by `serve --http`.
#include "ladder/Layout.h"

#include <cstddef>

namespace lj::ladder {

namespace web {
extern const char kLiveJs[];
extern const std::size_t kLiveJsSize;
extern const char kLiveCss[];
extern const std::size_t kLiveCssSize;
extern const char kEditorJs[];
extern const std::size_t kEditorJsSize;
extern const char kEditorCss[];
extern const std::size_t kEditorCssSize;
extern const char kTraceJs[];
extern const std::size_t kTraceJsSize;
extern const char kTraceCss[];
extern const std::size_t kTraceCssSize;
} // namespace web

std::string liveCss() { return std::string(web::kLiveCss, web::kLiveCssSize); }
std::string liveScript() { return std::string(web::kLiveJs, web::kLiveJsSize); }
std::string editorCss() { return std::string(web::kEditorCss, web::kEditorCssSize); }
std::string editorScript() { return std::string(web::kEditorJs, web::kEditorJsSize); }
std::string traceCss() { return std::string(web::kTraceCss, web::kTraceCssSize); }
std::string traceScript() { return std::string(web::kTraceJs, web::kTraceJsSize); }

} // namespace lj::ladder
