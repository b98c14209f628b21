// Builds the LLVM mirror of lj_state from abi.h and checks every offset against offsetof, so a
// change to the C header that is not reflected here fails loudly at the first compile.
#include "lowering/AbiTypes.h"

#include "ladderjit/abi.h"

#include <llvm/IR/Constants.h>
#include <llvm/IR/LLVMContext.h>

#include <cstddef>

namespace lj::lower {

namespace {

// Struct indices, in the order of the C declarations in abi.h.
enum ImageIdx : uint32_t { kImgD, kImgB, kImgP, kImgF, kImgG, kImgW, kImgX, kImgY, kImgR, kImgPad };
enum StateIdx : uint32_t {
  kStImg,
  kStT,
  kStC,
  kStPlsPrev,
  kStPlfPrev,
  kStAltPrev,
  kStAltState,
  kStEdge,
  kStNow,
  kStMaxSteps,
  kStSteps,
  kStNextSlice,
  kStLastFault,
  kStFaultWatchdog,
  kStFaultIndex,
  kStFaultDivzero,
  kStPad,
  kStInstWord,
  kStMem,
  kStHost
};

llvm::StructType *namedStruct(llvm::LLVMContext &ctx, llvm::ArrayRef<llvm::Type *> elems,
                              const char *name) {
  if (llvm::StructType *t = llvm::StructType::getTypeByName(ctx, name)) return t;
  return llvm::StructType::create(ctx, elems, name);
}

llvm::StructType *buildState(llvm::LLVMContext &ctx) {
  llvm::Type *i8 = llvm::Type::getInt8Ty(ctx), *i16 = llvm::Type::getInt16Ty(ctx);
  llvm::Type *i32 = llvm::Type::getInt32Ty(ctx), *i64 = llvm::Type::getInt64Ty(ctx);
  auto arr = [](llvm::Type *t, uint64_t n) { return llvm::ArrayType::get(t, n); };
  llvm::StructType *image = namedStruct(
      ctx,
      {arr(i32, LJ_D_COUNT), arr(i32, LJ_B_COUNT), arr(i32, LJ_P_COUNT), arr(i16, LJ_F_COUNT),
       arr(i16, LJ_G_COUNT), arr(i16, LJ_W_COUNT), arr(i8, LJ_X_COUNT), arr(i8, LJ_Y_COUNT),
       arr(i8, LJ_R_COUNT), arr(i8, sizeof(lj_image::pad_))},
      "lj_image");
  llvm::StructType *timer = namedStruct(ctx, {i64, i64, i8, i8, arr(i8, 6)}, "lj_timer");
  llvm::StructType *counter = namedStruct(ctx, {i32, i8, i8, arr(i8, 2)}, "lj_counter");
  return namedStruct(ctx,
                     {image, arr(timer, LJ_TC_SLOTS), arr(counter, LJ_TC_SLOTS),
                      arr(i8, LJ_BLOCK_SLOTS), arr(i8, LJ_BLOCK_SLOTS), arr(i8, LJ_BLOCK_SLOTS),
                      arr(i8, LJ_BLOCK_SLOTS), arr(i8, LJ_EDGE_SLOTS), i64, i64, i64, i32, i32, i32,
                      i32, i32, i32, arr(i32, LJ_INST_WORDS), arr(i8, LJ_MEM_BYTES),
                      llvm::PointerType::getUnqual(ctx)},
                     "lj_state");
}

// Every offset the lowering relies on, as the C compiler sees it.
struct Pin {
  llvm::SmallVector<uint64_t, 3> path;
  uint64_t offset;
  const char *what;
};

llvm::Error checkLayout(llvm::StructType *st, const llvm::DataLayout &dl) {
  const size_t img = offsetof(lj_state, img);
  const Pin pins[] = {
      {{kStImg, kImgD}, img + offsetof(lj_image, D), "D"},
      {{kStImg, kImgB}, img + offsetof(lj_image, B), "B"},
      {{kStImg, kImgP}, img + offsetof(lj_image, P), "P"},
      {{kStImg, kImgF}, img + offsetof(lj_image, F), "F"},
      {{kStImg, kImgG}, img + offsetof(lj_image, G), "G"},
      {{kStImg, kImgW}, img + offsetof(lj_image, W), "W"},
      {{kStImg, kImgX}, img + offsetof(lj_image, X), "X"},
      {{kStImg, kImgY}, img + offsetof(lj_image, Y), "Y"},
      {{kStImg, kImgR}, img + offsetof(lj_image, R), "R"},
      {{kStT, 0, 0}, offsetof(lj_state, T) + offsetof(lj_timer, start_ms), "T.start_ms"},
      {{kStT, 0, 1}, offsetof(lj_state, T) + offsetof(lj_timer, elapsed_ms), "T.elapsed_ms"},
      {{kStT, 0, 2}, offsetof(lj_state, T) + offsetof(lj_timer, out), "T.out"},
      {{kStT, 0, 3}, offsetof(lj_state, T) + offsetof(lj_timer, running), "T.running"},
      {{kStT, 1}, offsetof(lj_state, T) + sizeof(lj_timer), "T[1]"},
      {{kStC, 0, 0}, offsetof(lj_state, C) + offsetof(lj_counter, value), "C.value"},
      {{kStC, 0, 1}, offsetof(lj_state, C) + offsetof(lj_counter, out), "C.out"},
      {{kStC, 0, 2}, offsetof(lj_state, C) + offsetof(lj_counter, prev), "C.prev"},
      {{kStC, 1}, offsetof(lj_state, C) + sizeof(lj_counter), "C[1]"},
      {{kStPlsPrev}, offsetof(lj_state, pls_prev), "pls_prev"},
      {{kStPlfPrev}, offsetof(lj_state, plf_prev), "plf_prev"},
      {{kStAltPrev}, offsetof(lj_state, alt_prev), "alt_prev"},
      {{kStAltState}, offsetof(lj_state, alt_state), "alt_state"},
      {{kStEdge}, offsetof(lj_state, edge), "edge"},
      {{kStNow}, offsetof(lj_state, now_ms), "now_ms"},
      {{kStMaxSteps}, offsetof(lj_state, max_backward_steps), "max_backward_steps"},
      {{kStSteps}, offsetof(lj_state, steps), "steps"},
      {{kStNextSlice}, offsetof(lj_state, plc2_next_slice), "plc2_next_slice"},
      {{kStLastFault}, offsetof(lj_state, last_fault), "last_fault"},
      {{kStFaultWatchdog}, offsetof(lj_state, fault_watchdog), "fault_watchdog"},
      {{kStFaultIndex}, offsetof(lj_state, fault_index), "fault_index"},
      {{kStFaultDivzero}, offsetof(lj_state, fault_divzero), "fault_divzero"},
      {{kStInstWord}, offsetof(lj_state, inst_word), "inst_word"},
      {{kStMem}, offsetof(lj_state, mem), "mem"},
      {{kStHost}, offsetof(lj_state, host), "host"},
  };
  llvm::Type *i32 = llvm::Type::getInt32Ty(st->getContext());
  for (const Pin &p : pins) {
    llvm::SmallVector<llvm::Value *, 4> idx{llvm::ConstantInt::get(i32, 0)};
    for (uint64_t i : p.path) idx.push_back(llvm::ConstantInt::get(i32, i));
    uint64_t got = dl.getIndexedOffsetInType(st, idx);
    if (got != p.offset)
      return llvm::createStringError("lj_state layout mismatch at %s: LLVM %llu, abi.h %llu",
                                     p.what, (unsigned long long)got, (unsigned long long)p.offset);
  }
  if (dl.getTypeAllocSize(st) != sizeof(lj_state))
    return llvm::createStringError("lj_state size mismatch with abi.h");
  return llvm::Error::success();
}

uint32_t imageIndex(Area a) {
  switch (a) {
  case Area::DWord:
    return kImgD;
  case Area::Retained:
    return kImgB;
  case Area::Param:
    return kImgP;
  case Area::NcStatus:
    return kImgF;
  case Area::NcControl:
    return kImgG;
  case Area::Word:
    return kImgW;
  case Area::Input:
    return kImgX;
  case Area::Output:
    return kImgY;
  case Area::Relay:
    return kImgR;
  default:
    return ~0u;
  }
}

size_t imageOffset(Area a) {
  switch (a) {
  case Area::DWord:
    return offsetof(lj_image, D);
  case Area::Retained:
    return offsetof(lj_image, B);
  case Area::Param:
    return offsetof(lj_image, P);
  case Area::NcStatus:
    return offsetof(lj_image, F);
  case Area::NcControl:
    return offsetof(lj_image, G);
  case Area::Word:
    return offsetof(lj_image, W);
  case Area::Input:
    return offsetof(lj_image, X);
  case Area::Output:
    return offsetof(lj_image, Y);
  case Area::Relay:
    return offsetof(lj_image, R);
  default:
    return 0;
  }
}

/// Element width (bytes) and field name of a numeric area's lj_image array (abi.h).
struct ImageField {
  size_t bytes;
  const char *name;
};
ImageField imageField(Area a) {
#define LJ_FIELD(f)                                                                                \
  ImageField { sizeof(lj_image::f[0]), #f }
  switch (a) {
  case Area::DWord:
    return LJ_FIELD(D);
  case Area::Retained:
    return LJ_FIELD(B);
  case Area::Param:
    return LJ_FIELD(P);
  case Area::NcStatus:
    return LJ_FIELD(F);
  case Area::NcControl:
    return LJ_FIELD(G);
  case Area::Word:
    return LJ_FIELD(W);
  case Area::Input:
    return LJ_FIELD(X);
  case Area::Output:
    return LJ_FIELD(Y);
  case Area::Relay:
    return LJ_FIELD(R);
  default:
    return {0, "?"};
  }
#undef LJ_FIELD
}

} // namespace

llvm::Expected<StateLayout> StateLayout::create(llvm::LLVMContext &ctx, const llvm::DataLayout &dl,
                                                bool names) {
  StateLayout l;
  l.ctx_ = &ctx;
  l.names_ = names;
  l.state_ = buildState(ctx);
  if (llvm::Error e = checkLayout(l.state_, dl)) return e;
  return l;
}

uint64_t StateLayout::stateSize() { return sizeof(lj_state); }

StateLoc StateLayout::area(Area a, int32_t index) const {
  // The process image is abi.h's (the profile describes it; profiles/hnc8/Areas.cpp checks that
  // they agree), so the layout reads widths and names from the ABI itself.
  const ImageField field = imageField(a);
  StateLoc loc;
  loc.offset = static_cast<uint32_t>(offsetof(lj_state, img) + imageOffset(a) +
                                     static_cast<size_t>(index) * field.bytes);
  loc.type = llvm::Type::getIntNTy(*ctx_, static_cast<unsigned>(field.bytes * 8));
  loc.path = {kStImg, imageIndex(a), static_cast<uint32_t>(index)};
  if (names_) loc.name = field.name + std::to_string(index);
  return loc;
}

StateLoc StateLayout::timer(int32_t slot, TimerField f) const {
  static constexpr size_t kOff[] = {offsetof(lj_timer, start_ms), offsetof(lj_timer, elapsed_ms),
                                    offsetof(lj_timer, out), offsetof(lj_timer, running)};
  static constexpr const char *kName[] = {"start", "elapsed", "out", "running"};
  unsigned fi = static_cast<unsigned>(f);
  StateLoc loc;
  loc.offset = static_cast<uint32_t>(offsetof(lj_state, T) + slot * sizeof(lj_timer) + kOff[fi]);
  loc.type = fi < 2 ? llvm::Type::getInt64Ty(*ctx_) : llvm::Type::getInt8Ty(*ctx_);
  loc.path = {kStT, static_cast<uint32_t>(slot), fi};
  if (names_) loc.name = "T" + std::to_string(slot) + "." + kName[fi];
  return loc;
}

StateLoc StateLayout::counter(int32_t slot, CounterField f) const {
  static constexpr size_t kOff[] = {offsetof(lj_counter, value), offsetof(lj_counter, out),
                                    offsetof(lj_counter, prev)};
  static constexpr const char *kName[] = {"value", "out", "prev"};
  unsigned fi = static_cast<unsigned>(f);
  StateLoc loc;
  loc.offset = static_cast<uint32_t>(offsetof(lj_state, C) + slot * sizeof(lj_counter) + kOff[fi]);
  loc.type = fi == 0 ? llvm::Type::getInt32Ty(*ctx_) : llvm::Type::getInt8Ty(*ctx_);
  loc.path = {kStC, static_cast<uint32_t>(slot), fi};
  if (names_) loc.name = "C" + std::to_string(slot) + "." + kName[fi];
  return loc;
}

StateLoc StateLayout::block(BlockArray a, int32_t index) const {
  static constexpr size_t kOff[] = {offsetof(lj_state, pls_prev), offsetof(lj_state, plf_prev),
                                    offsetof(lj_state, alt_prev), offsetof(lj_state, alt_state)};
  static constexpr uint32_t kIdx[] = {kStPlsPrev, kStPlfPrev, kStAltPrev, kStAltState};
  static constexpr const char *kName[] = {"pls.prev", "plf.prev", "alt.prev", "alt.state"};
  unsigned ai = static_cast<unsigned>(a);
  StateLoc loc;
  loc.offset = static_cast<uint32_t>(kOff[ai] + index);
  loc.type = llvm::Type::getInt8Ty(*ctx_);
  loc.path = {kIdx[ai], static_cast<uint32_t>(index)};
  if (names_) loc.name = std::string(kName[ai]) + std::to_string(index);
  return loc;
}

StateLoc StateLayout::edge(int32_t slot) const {
  StateLoc loc;
  loc.offset = static_cast<uint32_t>(offsetof(lj_state, edge) + slot);
  loc.type = llvm::Type::getInt8Ty(*ctx_);
  loc.path = {kStEdge, static_cast<uint32_t>(slot)};
  if (names_) loc.name = "edge" + std::to_string(slot);
  return loc;
}

StateLoc StateLayout::memBytes(uint32_t offset, unsigned width, std::string name) const {
  StateLoc loc;
  loc.offset = offset;
  loc.type = llvm::Type::getIntNTy(*ctx_, width * 8);
  loc.path = {kStMem, static_cast<uint32_t>(offset - offsetof(lj_state, mem))};
  loc.align = 1;
  loc.span = static_cast<uint8_t>(width);
  if (names_) loc.name = std::move(name);
  return loc;
}

bool StateLayout::inMem(uint32_t offset) {
  return offset >= offsetof(lj_state, mem) && offset < offsetof(lj_state, mem) + LJ_MEM_BYTES;
}

StateLoc StateLayout::instWord(int32_t slot) const {
  StateLoc loc;
  loc.offset = static_cast<uint32_t>(offsetof(lj_state, inst_word) + slot * sizeof(int32_t));
  loc.type = llvm::Type::getInt32Ty(*ctx_);
  loc.path = {kStInstWord, static_cast<uint32_t>(slot)};
  if (names_) loc.name = "inst" + std::to_string(slot);
  return loc;
}

StateLoc StateLayout::scalar(Scalar s) const {
  StateLoc loc;
  switch (s) {
  case Scalar::NowMs:
    loc = {offsetof(lj_state, now_ms), llvm::Type::getInt64Ty(*ctx_), {kStNow}, "now_ms"};
    break;
  case Scalar::MaxSteps:
    loc = {offsetof(lj_state, max_backward_steps),
           llvm::Type::getInt64Ty(*ctx_),
           {kStMaxSteps},
           "max_steps"};
    break;
  case Scalar::Steps:
    loc = {offsetof(lj_state, steps), llvm::Type::getInt64Ty(*ctx_), {kStSteps}, "steps"};
    break;
  case Scalar::FaultIndex:
    loc = {offsetof(lj_state, fault_index),
           llvm::Type::getInt32Ty(*ctx_),
           {kStFaultIndex},
           "fault_index"};
    break;
  case Scalar::Host:
    loc = {offsetof(lj_state, host), llvm::PointerType::getUnqual(*ctx_), {kStHost}, "host"};
    break;
  case Scalar::FaultDivzero:
    loc = {offsetof(lj_state, fault_divzero),
           llvm::Type::getInt32Ty(*ctx_),
           {kStFaultDivzero},
           "fault_divzero"};
    break;
  }
  return loc;
}

llvm::Value *StateLayout::address(llvm::IRBuilderBase &b, llvm::Value *state,
                                  const StateLoc &loc) const {
  // A byte offset (validated against the struct above): already the form InstCombine would
  // canonicalize a struct GEP into, so the optimizer has nothing to redo.
  return b.CreateConstInBoundsGEP1_64(b.getInt8Ty(), state, loc.offset,
                                      names_ ? loc.name + ".addr" : llvm::Twine());
}

} // namespace lj::lower
