// libFuzzer target for the ladder network JSON as every command and the page editor's drafts
// take it (docs/ladder-json.md): any bytes as the JSON of a FANUC or an IEC IL program (the
// first byte chooses which), read against that program -> networks -> program text in the
// dialect (untouched rungs copied, edited ones printed, COME kept between rungs) -> front end
// and verifier -> the networks must hold the JSON's statements; the edited networks are drawn
// too (layout, SVG, text form). A refusal anywhere is fine (the product also refuses a printed
// program whose networks hold other statements than the JSON); a crash, hang or sanitizer
// report is not.
#include "ladder/Json.h"
#include "ladder/Layout.h"
#include "ladder/Text.h"
#include "pipeline/Compile.h"
#include "tests/fuzz/ProgramInvariants.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>

namespace {

// The sources the JSON is read against: instructions recorded as written (DEC, GTB, SUB 25 with
// (PRM) lines, CALLU), COM..COME and NOP between rungs; IL with numbered lines, XOR, N, ENDC,
// an operation block, a comparison, a timer block and a subroutine.
constexpr std::string_view kPmc = "RD X0.0\n"
                                  "COM\n"
                                  "RD X0.1\n"
                                  "DEC F10 0311\n"
                                  "WRT R0.0\n"
                                  "COME\n"
                                  "; after the common line\n"
                                  "RD X0.2\n"
                                  "GTB D100 5 ; over five\n"
                                  "WRT R0.1\n"
                                  "NOP\n"
                                  "RD X0.3\n"
                                  "SUB 25\n"
                                  "(PRM) 0001\n"
                                  "(PRM) D0\n"
                                  "(PRM) 100\n"
                                  "(PRM) R10\n"
                                  "RD X0.4\n"
                                  "OR.NOT R0.1\n"
                                  "TMRB 1 500\n"
                                  "WRT.NOT Y0.0\n"
                                  "END1\n"
                                  "CALLU P1\n"
                                  "END2\n"
                                  "SP P1\n"
                                  "RD X0.5\n"
                                  "SET R0.3\n"
                                  "SPE\n"
                                  "END\n";
constexpr std::string_view kIl = "(* numbered as the Neza software writes it *)\n"
                                 "000 LD %S1\n"
                                 "001 ENDC\n"
                                 "002 LD %I0.1\n"
                                 "003 XOR %I0.2\n"
                                 "004 ST %Q0.1\n"
                                 "LD %I0.3\n"
                                 "N\n"
                                 "ST %Q0.2\n"
                                 "LD [%MW0 > 5]\n"
                                 "[%MW1 := %MW1 + 1]\n"
                                 "BLK %TM0\n"
                                 "LD %I0.4\n"
                                 "IN\n"
                                 "OUT_BLK\n"
                                 "LD Q\n"
                                 "ST %Q0.3\n"
                                 "END_BLK\n"
                                 "LD %I0.5\n"
                                 "SR0\n"
                                 "END\n"
                                 "SR0:\n"
                                 "LD %M1\n"
                                 "ST %M2\n"
                                 "RET\n";

std::optional<lj::VerifiedProgram> compile(bool fanuc, std::string_view text, const char *file) {
  lj::Diagnostics d(file);
  return fanuc ? lj::pipeline::compilePmc(text, file, lj::VerifyOptions{}, d, nullptr)
               : lj::pipeline::compileIl(text, file, lj::VerifyOptions{}, d);
}

const lj::VerifiedProgram &source(bool fanuc) {
  static const std::optional<lj::VerifiedProgram> pmc = compile(true, kPmc, "src.pmc");
  static const std::optional<lj::VerifiedProgram> il = compile(false, kIl, "src.il");
  const std::optional<lj::VerifiedProgram> &p = fanuc ? pmc : il;
  if (!p) __builtin_trap(); // the sources themselves must verify
  return *p;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  if (size == 0) return 0;
  const bool fanuc = (data[0] & 1) == 0;
  const std::string_view json(reinterpret_cast<const char *>(data) + 1, size - 1);
  const lj::VerifiedProgram &src = source(fanuc);
  lj::ladder::Networks nets;
  std::string error, text;
  if (!lj::ladder::readJson(json, nets, error, *src.dialect)) return 0;
  // The edited networks drawn, as `ladderjit ladder x.json` and the page do.
  (void)lj::ladder::renderText(nets);
  (void)lj::ladder::renderSvg(lj::ladder::layout(nets));
  std::vector<lj::ladder::LineOrigin> origins;
  if (!lj::ladder::programText(nets, src, fanuc ? kPmc : kIl, text, error, false, &origins))
    return 0;
  std::optional<lj::VerifiedProgram> again = compile(fanuc, text, fanuc ? "j.pmc" : "j.il");
  if (!again) return 0;
  lj::fuzztest::checkProgramInvariants(*again);
  (void)lj::ladder::sameStatementsAs(nets, lj::ladder::fromProgram(*again), error);
  return 0;
}
