// The Neza function blocks %TMi / %Ci in IL (modicon-neza.md 3; docs/iec-il.md "Function
// blocks"): CONFIG lines, the reversible BLK ... OUT_BLK ... END_BLK form, the instruction form
// (`IN %TMi`, `CU %Ci`...), bare outputs inside a block, and the presets the init part loads.
// The Parser checks where an instruction may stand; this class emits the IR (Op::IecTimer,
// Op::IecCounter) and keeps the per-block facts.
#pragma once

#include "frontends/iec/Emitter.h"
#include "frontends/iec/Objects.h"

#include <array>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace lj::iec {

class FunctionBlocks {
public:
  FunctionBlocks(Emitter &em, Diagnostics &diags) : em_(em), diags_(diags) {}

  /// Where the parser is: outside a block, in its input section (BLK .. OUT_BLK / END_BLK) or
  /// in its output section (OUT_BLK .. END_BLK).
  enum class Section : uint8_t { None, Inputs, Outputs };
  Section section() const {
    return open_ ? (open_->outputs ? Section::Outputs : Section::Inputs) : Section::None;
  }
  /// "BLK %C8 (line 4)", for messages about the open block.
  std::string openBlock() const;

  /// `CONFIG %TMi [TON|TOF|TP] [TB=1MIN|1S|100MS|10MS|1MS] [P=n]` / `CONFIG %Ci [P=n]`; `args`
  /// after the keyword.
  void config(std::string_view args, SourceLoc loc);
  /// BLK with its operand `text` (the parser has closed the sequence before it).
  void begin(std::string_view text, SourceLoc loc, SourceLoc opLoc);
  /// OUT_BLK: the block runs here.
  void outputs(SourceLoc loc);
  /// END_BLK: the block runs here unless OUT_BLK ran it.
  void end(SourceLoc loc);
  /// An input instruction with no operand inside the input section (IN; R, S, CU, CD), taking
  /// the accumulator.
  void pin(const std::string &mnem, SourceLoc loc);
  /// Whether `obj` is a block the instruction form `mnem obj` applies to (R / S of a counter).
  static bool isBlock(const Object &obj) {
    return obj.cls == ObjClass::Timer || obj.cls == ObjClass::Counter;
  }
  /// The instruction form `mnem %TMi` / `mnem %Ci`: the block runs with the accumulator on
  /// that one input, which the accumulator keeps.
  void direct(const std::string &mnem, const Object &blk, SourceLoc loc, SourceLoc opLoc);
  /// A bare output name (E, D, F, Q): the open block's output inside its output section, an
  /// error elsewhere; nullopt with no error when `name` is not one.
  std::optional<Object> bare(std::string_view name, SourceLoc loc, bool &isBare);
  /// A block object was named (its preset is loaded at power-up).
  void use(const Object &obj);
  /// A BLK still open before `where` (a label, a subroutine, the end) is an error.
  void mustBeClosed(SourceLoc loc, const std::string &where);
  /// The power-up statements (LD 1, then preset := its configured value for every block named)
  /// for the init part.
  std::vector<Stmt> presets(SourceLoc loc) const;

private:
  struct Config {
    int32_t type = 0;      ///< TimerType
    int32_t timeBase = 0;  ///< kTimeBaseMs code (1 min: the default, L1274)
    int32_t preset = 9999; ///< the default (L1276-1278, L1098)
    SourceLoc loc;         ///< of its CONFIG line (line 0: defaults)
  };
  struct Open {
    Object blk;
    SourceLoc loc;
    bool outputs = false, ran = false;
    std::array<std::optional<Operand>, 4> pins; ///< latched input: timer IN = [0]; R S CU CD
  };
  static std::string name(const Object &blk);
  Config &configOf(const Object &blk);
  /// Run the open block on its latched inputs.
  void run(SourceLoc loc);
  /// The never-written scratch bit (a constant 0 for inputs nothing drives).
  Operand zero(SourceLoc loc);
  /// The index of input `mnem` of `blk` (0 for IN; 0..3 for R S CU CD), or -1 with an error.
  int pinIndex(const Object &blk, const std::string &mnem, SourceLoc loc);

  Emitter &em_;
  Diagnostics &diags_;
  std::map<std::pair<int, int32_t>, Config> configs_; ///< (0 timer / 1 counter, number)
  std::optional<Open> open_;
  std::optional<Operand> zero_;
};

} // namespace lj::iec
