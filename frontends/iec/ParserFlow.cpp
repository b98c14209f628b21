// The IEC IL parser, program parts and flow: `%Li :` labels and `SRi :` subroutine headers,
// JMP / JMPC / JMPCN, END / ENDC / ENDCN, RET / RETC / RETCN and SRi calls.
#include "frontends/iec/ParserInternal.h"

#include "ir/IecBlocks.h"
#include "profiles/iec/IecProfile.h"

namespace lj::iec::detail {

void IlParser::afterMain(SourceLoc loc) {
  if (mainEnded_ && sub_ < 0 && !afterEndReported_) {
    error(loc, "LJ2043",
          "instruction after END outside a subroutine (after END only SRi : blocks follow)");
    afterEndReported_ = true;
  }
}

void IlParser::finishMain(SourceLoc loc) {
  // END / ENDC / ENDCN jump here.
  Operand end;
  end.kind = Operand::Kind::Reg;
  end.area = Area::Label;
  end.index = kEndLabel;
  em_.emit(Op::Label, loc, {end});
  mainDone_ = true;
}

void IlParser::header(std::string_view name, SourceLoc loc) {
  std::string err;
  std::optional<Object> obj = parseObject(name, err);
  if (!obj || (obj->cls != ObjClass::Label && obj->cls != ObjClass::Sub)) {
    error(loc, "LJ2044", obj ? "expected %Li : or SRi :" : err);
    return;
  }
  blocks_.mustBeClosed(loc, obj->cls == ObjClass::Label ? "a label" : "a subroutine");
  closeSequence(loc, obj->cls == ObjClass::Label ? "a label" : "a subroutine");
  seq_ = false;
  Operand op = obj->op;
  op.loc = loc;
  if (obj->cls == ObjClass::Label) {
    afterMain(loc);
    em_.emit(Op::Label, loc, {op});
    return;
  }
  if (!mainDone_) finishMain(loc);
  mainEnded_ = true;
  if (sub_ >= 0) em_.emit(Op::SubEnd, loc);
  em_.emit(Op::SubBegin, loc, {op});
  sub_ = obj->number;
}

std::optional<Operand> IlParser::label(std::string_view text, SourceLoc opLoc,
                                       const std::string &mnem) {
  std::optional<Object> obj = object(text, opLoc, mnem);
  if (!obj) return std::nullopt;
  if (obj->cls != ObjClass::Label) {
    error(opLoc, "LJ2045", mnem + " needs a label %Li, found '" + std::string(text) + "'");
    return std::nullopt;
  }
  return obj->op;
}

void IlParser::jump(const std::string &mnem, std::string_view text, SourceLoc loc,
                    SourceLoc opLoc) {
  afterMain(loc);
  if (!outsideBlock(loc, mnem)) return;
  if (mnem != "JMP" && !needSequence(loc, mnem)) return;
  if (!outsideParens(loc, mnem)) return;
  std::optional<Operand> l = label(text, opLoc, mnem);
  if (!l) return;
  if (mnem == "JMP") {
    em_.emit(Op::LoadTrue, loc); // unconditional: needs no LD 1 (L481-489)
    em_.emit(Op::Jump, loc, {*l});
    seq_ = true;
  } else if (mnem == "JMPC") {
    em_.emit(Op::Jump, loc, {*l});
  } else {
    nonReversible(loc, mnem);
    em_.negate(loc);
    em_.emit(Op::Jump, loc, {*l});
    em_.negate(loc);
  }
}

void IlParser::end(const std::string &mnem, std::string_view text, SourceLoc loc, SourceLoc opLoc) {
  if (!text.empty()) error(opLoc, "LJ2046", mnem + " takes no operand");
  if (!outsideBlock(loc, mnem)) return;
  if (sub_ >= 0) {
    error(loc, "LJ2047",
          mnem + " inside a subroutine is not supported (the scan ends after the main "
                 "program; use RET)");
    return;
  }
  afterMain(loc);
  if (mnem != "END" && !needSequence(loc, mnem)) return;
  if (!outsideParens(loc, mnem)) return;
  Operand end;
  end.kind = Operand::Kind::Reg;
  end.area = Area::Label;
  end.index = kEndLabel;
  end.loc = loc;
  if (mnem == "END") {
    closeSequence(loc, "END");
    em_.emit(Op::LoadTrue, loc);
    em_.emit(Op::Jump, loc, {end});
    mainEnded_ = true;
    seq_ = false;
  } else if (mnem == "ENDC") {
    em_.emit(Op::Jump, loc, {end});
  } else {
    nonReversible(loc, mnem);
    em_.negate(loc);
    em_.emit(Op::Jump, loc, {end});
    em_.negate(loc);
  }
}

void IlParser::ret(const std::string &mnem, std::string_view text, SourceLoc loc, SourceLoc opLoc) {
  if (!text.empty()) error(opLoc, "LJ2048", mnem + " takes no operand");
  if (!outsideBlock(loc, mnem)) return;
  if (sub_ < 0) {
    error(loc, "LJ2049", mnem + " outside a subroutine");
    return;
  }
  if (mnem != "RET" && !needSequence(loc, mnem)) return;
  if (!outsideParens(loc, mnem)) return;
  if (mnem == "RET") {
    closeSequence(loc, "RET");
    em_.emit(Op::LoadTrue, loc);
    em_.emit(Op::Return, loc);
    seq_ = false;
  } else if (mnem == "RETC") {
    em_.emit(Op::Return, loc);
  } else {
    em_.negate(loc);
    em_.emit(Op::Return, loc);
    em_.negate(loc);
  }
}

void IlParser::call(const std::string &mnem, std::string_view text, SourceLoc loc,
                    SourceLoc opLoc) {
  if (!text.empty()) error(opLoc, "LJ2050", mnem + " takes no operand");
  if (!outsideBlock(loc, mnem)) return;
  afterMain(loc);
  if (!needSequence(loc, mnem) || !outsideParens(loc, mnem)) return;
  std::string err;
  std::optional<Object> obj = parseObject(mnem, err);
  if (!obj) {
    error(loc, "LJ2051", err);
    return;
  }
  obj->op.loc = loc;
  em_.emit(Op::Call, loc, {obj->op});
}

} // namespace lj::iec::detail
