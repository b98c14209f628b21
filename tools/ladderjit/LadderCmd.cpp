// `ladderjit ladder`: PROGRAM as ladder networks (docs/ladder-json.md), as readable text or as the
// network JSON that every command accepts back as PROGRAM.
#include "tools/ladderjit/Commands.h"

#include "formats/OutputFile.h"
#include "ladder/Json.h"
#include "ladder/Layout.h"
#include "ladder/Text.h"

#include <cstdio>
#include <fstream>
#include <iostream>

namespace lj::cli {

int runLadder(const LadderArgs &a) {
  if (a.format != "text" && a.format != "json" && a.format != "svg" && a.format != "html" &&
      a.format != "layout")
    return usageError("ladder --format must be text, json, svg, html or layout, got '" + a.format +
                      "'");
  int code = kOk;
  ProgramSource src;
  if (!readProgram(a.program, src, code, a.dialect)) return code;
  std::optional<VerifiedProgram> prog =
      loadProgram(src, effectiveNvalue(src, a.plc2Nvalue, a.plc2NvalueGiven), code,
                  a.quiet ? WarningReport::None : WarningReport::Summary, a.dialect);
  if (!prog) return code;
  ladder::Networks nets = ladder::fromProgram(*prog);
  std::string out;
  if (a.format == "json")
    // Another dialect's JSON carries its program text: it is read back through it.
    out = ladder::writeJson(nets, src.dialect == &pipeline::defaultDialect() ? "" : src.text);
  else if (a.format == "text")
    out = ladder::renderText(nets);
  else {
    ladder::Layout l = ladder::layout(nets);
    out = a.format == "svg"    ? ladder::renderSvg(l)
          : a.format == "html" ? ladder::renderHtml(l)
                               : ladder::layoutJson(l);
  }
  if (a.output.empty() || a.output == "-") {
    std::cout << out << std::flush;
    return kOk;
  }
  std::string error; // one output-file function for every command (formats/OutputFile.h)
  if (!formats::writeOutputFile(a.output, out, error)) return usageError("-o: " + error);
  return kOk;
}

} // namespace lj::cli
