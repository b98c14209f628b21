// The operand formatter core (frontends/common/OperandText.h).
#include "frontends/common/OperandText.h"

namespace lj::frontend {

std::string constantText(int32_t value) { return std::to_string(value); }

std::string operandText(const TargetProfile &tp, const Operand &op) {
  switch (op.kind) {
  case Operand::Kind::None:
    return "";
  case Operand::Kind::Const:
    return constantText(op.value);
  case Operand::Kind::Reg:
  case Operand::Kind::Bit: {
    std::string s(tp.area(op.area).name);
    s += std::to_string(op.index);
    if (op.kind == Operand::Kind::Bit) {
      s += '.'; // appended separately: GCC 12 -O3 warns (-Wrestrict) on "." + std::string
      s += std::to_string(op.bit);
    }
    return s;
  }
  }
  return "";
}

} // namespace lj::frontend
