// The per-object edge image of ir/Profile.h EdgePolicy::PerObject: edge[k] := the bit of
// VerifiedProgram::edgeObjects[k] after the cyclic part's body, however the body ended.
#include "lowering/EdgeImage.h"

#include "ladderjit/abi.h"

namespace lj::lower {

bool hasEdgeImage(const VerifiedProgram &prog) {
  for (const Operand &o : prog.edgeObjects)
    if (o.kind == Operand::Kind::Bit) return true;
  return false;
}

void emitEdgeImageEntry(ModuleContext &mc, llvm::Function *entry, llvm::Function *body) {
  llvm::LLVMContext &ctx = entry->getContext();
  llvm::IRBuilder<> b(llvm::BasicBlock::Create(ctx, "entry", entry));
  llvm::Value *state = entry->getArg(1);
  llvm::Value *status = b.CreateCall(body, {entry->getArg(0), state}, "status");
  for (size_t k = 0; k < mc.prog.edgeObjects.size(); ++k) {
    const Operand &o = mc.prog.edgeObjects[k];
    if (o.kind != Operand::Kind::Bit) continue;
    StateLoc src;
    int bit = o.bit;
    if (o.area == Area::Timer || o.area == Area::Counter) {
      const int slot = mc.prog.profile->tcSlot(o.area, o.index);
      src = o.area == Area::Timer ? mc.layout.timer(slot, TimerField::Out)
                                  : mc.layout.counter(slot, CounterField::Out);
      bit = 0;
    } else {
      const TargetProfile &tp = *mc.prog.profile;
      const uint32_t off = tp.elementOffset(o.area, o.index);
      src = StateLayout::inMem(off) ? mc.layout.memBytes(off, tp.area(o.area).bytes)
                                    : mc.layout.area(o.area, o.index);
    }
    llvm::LoadInst *v = b.CreateLoad(src.type, mc.layout.address(b, state, src));
    if (src.align) v->setAlignment(llvm::Align(src.align));
    llvm::Value *on = b.CreateICmpNE(
        b.CreateAnd(v, llvm::ConstantInt::get(src.type, llvm::APInt::getOneBitSet(
                                                            src.type->getIntegerBitWidth(), bit))),
        llvm::ConstantInt::get(src.type, 0));
    const StateLoc dst = mc.layout.edge(static_cast<int32_t>(k));
    b.CreateStore(b.CreateZExt(on, b.getInt8Ty()), mc.layout.address(b, state, dst));
  }
  b.CreateRet(status);
}

} // namespace lj::lower
