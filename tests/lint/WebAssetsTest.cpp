// The web files embedded into the binary (ladder/web/embed.cmake) are the files in ladder/web/,
// byte for byte: fails when a build serves a stale or altered copy.
// Usage: ladderjit_web_assets_test SOURCE_DIR
#include "ladder/Layout.h"

#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

namespace {

int compare(const std::string &path, const std::string &embedded) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    std::printf("FAIL: cannot read %s\n", path.c_str());
    return 1;
  }
  std::ostringstream ss;
  ss << in.rdbuf();
  const std::string file = ss.str();
  if (file == embedded) {
    std::printf("ok: %s: the embedded copy is the file (%zu bytes)\n", path.c_str(), file.size());
    return 0;
  }
  size_t at = 0;
  while (at < file.size() && at < embedded.size() && file[at] == embedded[at]) ++at;
  std::printf("FAIL: %s: the embedded copy differs from the file at byte %zu (file %zu bytes, "
              "embedded %zu)\n",
              path.c_str(), at, file.size(), embedded.size());
  return 1;
}

} // namespace

int main(int argc, char **argv) {
  if (argc != 2) {
    std::printf("usage: ladderjit_web_assets_test SOURCE_DIR\n");
    return 2;
  }
  const std::string web = std::string(argv[1]) + "/ladder/web/";
  int bad = 0;
  bad += compare(web + "live.js", lj::ladder::liveScript());
  bad += compare(web + "live.css", lj::ladder::liveCss());
  bad += compare(web + "editor.js", lj::ladder::editorScript());
  bad += compare(web + "editor.css", lj::ladder::editorCss());
  bad += compare(web + "trace.js", lj::ladder::traceScript());
  bad += compare(web + "trace.css", lj::ladder::traceCss());
  return bad ? 1 : 0;
}
