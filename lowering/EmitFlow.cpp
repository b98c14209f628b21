// Statement dispatch and control flow (docs/dialect-notes.md "Flow"): JMP/LBL become basic
// blocks, LOOP/NEXT a counted loop with a phi, CALL a call of the subroutine's function whose
// fault code is propagated, and the watchdog `if (++steps > max) return LJ_FAULT_WATCHDOG`.
#include "lowering/FunctionEmitter.h"

#include "ir/SyncInputs.h"

#include "ladderjit/abi.h"

namespace lj::lower {

FunctionEmitter::FunctionEmitter(ModuleContext &mc, llvm::Function *fn, llvm::Value *state,
                                 uint32_t retnStatus)
    : mc_(mc), prog_(mc.prog), fn_(fn),
      b_(fn->getContext(), llvm::InstSimplifyFolder(mc.mod.getDataLayout())), state_(state),
      cache_(mc.layout, b_, state), retnStatus_(retnStatus) {
  b_.SetInsertPoint(llvm::BasicBlock::Create(fn->getContext(), "entry", fn));
}

llvm::Error FunctionEmitter::fail(int32_t i, const std::string &what) const {
  const Stmt &s = prog_.stmts[i];
  return llvm::createStringError("%s:%d:%d: internal error: lowering %s: %s", prog_.file.c_str(),
                                 s.loc.line, s.loc.col, spelling(prog_.dialect, s.op),
                                 what.c_str());
}

llvm::BasicBlock *FunctionEmitter::newBlock(const char *name) {
  return llvm::BasicBlock::Create(fn_->getContext(), name, fn_);
}

void FunctionEmitter::continueIn(llvm::BasicBlock *bb) {
  cache_.flush();
  b_.CreateBr(bb);
  b_.SetInsertPoint(bb);
}

llvm::BasicBlock *FunctionEmitter::labelBlock(int32_t lblIndex) {
  auto [it, fresh] = labels_.try_emplace(lblIndex, nullptr);
  if (fresh) {
    it->second = llvm::BasicBlock::Create(fn_->getContext(),
                                          std::string(tp().area(Area::Label).name) +
                                              std::to_string(prog_.stmts[lblIndex].ops[0].index),
                                          fn_);
  }
  return it->second;
}

llvm::Error FunctionEmitter::emitRange(StmtRange r, int32_t deadDepth, const ChunkPlan *chunk,
                                       const CarryBuffer *carry) {
  st_.assign(static_cast<size_t>(deadDepth), b_.getFalse()); // dead entries read as 0
  ms_.clear();
  chunk_ = chunk && carry ? chunk : nullptr;
  range_ = r;
  syncReads_ = readsSyncInputs(prog_, r.begin); // a body never spans two parts
  if (carry) carry_ = *carry;
  if (chunk_ && carry_.buf) {
    ms_.assign(static_cast<size_t>(prog_.info[r.begin].msDepth), b_.getFalse());
    // Live entries of a carried cut: only the positions this chunk touches.
    auto load = [&](std::vector<llvm::Value *> &stack, int32_t from, int32_t base) {
      for (int32_t k = std::max(from, 0); from >= 0 && k < static_cast<int32_t>(stack.size());
           ++k) {
        llvm::Value *p = b_.CreateConstInBoundsGEP1_32(b_.getInt8Ty(), carry_.buf, base + k);
        stack[k] = b_.CreateTrunc(b_.CreateLoad(b_.getInt8Ty(), p), b_.getInt1Ty());
      }
    };
    load(st_, chunk_->stLoad, 0);
    load(ms_, chunk_->msLoad, carry_.msBase);
  }
  for (int32_t i = r.begin; i < r.end; ++i) {
    const StmtInfo &info = prog_.info[i];
    if (static_cast<int32_t>(st_.size()) != info.depth ||
        static_cast<int32_t>(ms_.size()) != info.msDepth)
      return fail(i, "stack depth " + std::to_string(st_.size()) + "/" +
                         std::to_string(ms_.size()) + " differs from the verifier's " +
                         std::to_string(info.depth) + "/" + std::to_string(info.msDepth));
    if (prog_.stmts[i].op == Op::LoopBegin && outlines(i)) {
      if (info.target < i || info.target >= r.end)
        return fail(i, "a loop begin without its loop end in this body");
      emitOutlinedLoop(i);
      i = info.target; // the body and its NEXT are lowered in the loop's own function
      continue;
    }
    if (llvm::Error e = emitStmt(i)) return e;
  }
  if (!loops_.empty())
    return fail(loops_.back().loopIndex, "LoopBegin without LoopEnd in this body");
  return llvm::Error::success();
}

llvm::Error FunctionEmitter::finish() {
  cache_.flush();
  if (chunk_ && carry_.buf) { // hand the live entries of the cut after this chunk to the next one
    auto store = [&](const std::vector<llvm::Value *> &stack, int32_t from, int32_t base) {
      for (int32_t k = std::max(from, 0); from >= 0 && k < static_cast<int32_t>(stack.size());
           ++k) {
        llvm::Value *p = b_.CreateConstInBoundsGEP1_32(b_.getInt8Ty(), carry_.buf, base + k);
        b_.CreateStore(b_.CreateZExt(stack[k], b_.getInt8Ty()), p);
      }
    };
    store(st_, chunk_->stStore, 0);
    store(ms_, chunk_->msStore, carry_.msBase);
  }
  b_.CreateRet(b_.getInt32(LJ_FAULT_NONE));
  for (auto &[index, bb] : labels_)
    if (!bb->getTerminator()) return fail(index, "jump target outside the lowered body");
  return llvm::Error::success();
}

llvm::Error FunctionEmitter::emitStmtBody(int32_t i) {
  const Stmt &s = prog_.stmts[i];
  const InstrInfo &row = instrInfo(s.op);
  switch (s.op) {
  case Op::Jump:
    return emitJmp(i);
  case Op::Label:
    emitLabel(i);
    return llvm::Error::success();
  case Op::LoopBegin:
    emitLoop(i);
    return llvm::Error::success();
  case Op::LoopEnd:
    return emitNext(i);
  case Op::Call:
    return emitCall(i);
  case Op::JumpOut:
    return emitJumpOut(i);
  case Op::Return:
    emitRetn();
    return llvm::Error::success();
  default:
    break;
  }
  switch (opFamily(s.op)) {
  case Family::Data:
    return emitDataBlock(i);
  case Family::Nc:
    return emitNcBlock(i);
  case Family::Cnc:
    return emitCncBlock(i);
  case Family::PmcTc:
    return emitPmcTcBlock(i);
  case Family::ClassicLadder:
    return emitClassicLadderBlock(i);
  case Family::Core:
    break;
  }
  switch (row.stack) {
  case StackRule::Structural: // markers, SP, SPE: both stacks emptied
    st_.clear();
    ms_.clear();
    return llvm::Error::success();
  case StackRule::Block: {
    const StmtInfo &info = prog_.info[i];
    if (row.inputs == 1 && info.hasInput == st_.empty())
      return fail(i, "verifier's hasInput disagrees with the ST depth");
    return emitBlock(i);
  }
  default:
    return emitBasic(i);
  }
}

void FunctionEmitter::watchdogStep(llvm::BasicBlock *next) {
  // Checked in the current block after the cache was flushed, so an abort leaves the image
  // exactly as written so far. The abort path stores the incremented count too.
  StateLoc stepsL = mc_.layout.scalar(Scalar::Steps);
  llvm::Value *steps = b_.CreateAdd(cache_.load(stepsL), b_.getInt64(1), "steps.next");
  llvm::Value *max = cache_.load(mc_.layout.scalar(Scalar::MaxSteps));
  cache_.store(stepsL, steps);
  cache_.flush();
  if (!abort_) {
    abort_ = llvm::BasicBlock::Create(fn_->getContext(), "watchdog", fn_);
    llvm::IRBuilder<> ab(abort_);
    ab.CreateRet(ab.getInt32(LJ_FAULT_WATCHDOG));
  }
  b_.CreateCondBr(b_.CreateICmpUGT(steps, max), abort_, next);
}

llvm::BasicBlock *FunctionEmitter::jumpTarget(int32_t lbl) {
  if (lbl >= range_.begin && lbl < range_.end) return labelBlock(lbl);
  // The label starts another chunk of this body: its dispatcher goes on there.
  if (!carry_.labelChunk || !carry_.labelChunk->count(lbl)) return nullptr;
  llvm::BasicBlock *bb = newBlock("jump.chunk");
  llvm::IRBuilder<> jb(bb);
  jb.CreateRet(jb.getInt32(kStatusJump + carry_.labelChunk->at(lbl)));
  return bb;
}

llvm::Error FunctionEmitter::emitJmp(int32_t i) {
  const StmtInfo &info = prog_.info[i];
  if (info.target < 0 || prog_.stmts[info.target].op != Op::Label)
    return fail(i, "jump target is not a Label");
  llvm::Value *en = enable(); // ST is left as it is
  llvm::BasicBlock *target = jumpTarget(info.target);
  if (!target) return fail(i, "jump target outside the lowered body");
  llvm::BasicBlock *cont = newBlock("nojump");
  cache_.flush();
  if (info.backward) {
    llvm::BasicBlock *taken = newBlock("backjump");
    b_.CreateCondBr(en, taken, cont);
    b_.SetInsertPoint(taken);
    watchdogStep(target);
  } else {
    b_.CreateCondBr(en, target, cont);
  }
  b_.SetInsertPoint(cont);
  return llvm::Error::success();
}

void FunctionEmitter::emitLabel(int32_t i) {
  continueIn(labelBlock(i));
  st_.clear();
  ms_.clear();
}

FunctionEmitter::Loop FunctionEmitter::openLoop(int32_t i) {
  // The count is read once on entry; each iteration (the first included) is one watchdog step
  // taken before its body; a count <= 0 skips the body.
  llvm::Value *count = readInt(prog_.stmts[i].ops[0]);
  cache_.flush();
  llvm::BasicBlock *pre = b_.GetInsertBlock();
  llvm::BasicBlock *header = newBlock("loop");
  llvm::BasicBlock *check = newBlock("loop.step");
  llvm::BasicBlock *body = newBlock("loop.body");
  llvm::BasicBlock *exit = newBlock("loop.end");
  b_.CreateBr(header);
  b_.SetInsertPoint(header);
  llvm::PHINode *remaining = b_.CreatePHI(b_.getInt32Ty(), 2, "remaining");
  remaining->addIncoming(count, pre);
  // Built without the simplifying folder: with only its entry value yet, the phi would let
  // InstSimplify fold the test to a constant.
  llvm::Value *more =
      b_.Insert(new llvm::ICmpInst(llvm::ICmpInst::ICMP_SGT, remaining, b_.getInt32(0)));
  b_.CreateCondBr(more, check, exit);
  b_.SetInsertPoint(check);
  watchdogStep(body);
  b_.SetInsertPoint(body);
  return {i, header, remaining, exit};
}

void FunctionEmitter::emitLoop(int32_t i) {
  loops_.push_back(openLoop(i));
  st_.clear();
  ms_.clear();
}

bool FunctionEmitter::outlines(int32_t loopIndex) const {
  const int32_t limit = mc_.opts.chunkStatements;
  const std::vector<int64_t> &w = mc_.weightBefore;
  return limit > 0 && w[prog_.info[loopIndex].target] - w[loopIndex + 1] > limit;
}

void FunctionEmitter::emitOutlinedLoop(int32_t i) {
  // The same loop as emitLoop (count read once, one watchdog step before each iteration), with
  // the body a call. The body function returns 0, a fault (watchdog) that ends the tick, or
  // kStatusReturn for a RETN taken inside it, which returns from this function as a RETN here.
  const int32_t next = prog_.info[i].target;
  // Named after the top-level body and the LOOP's statement index (unique in the program), not
  // after the enclosing function: a nest of n outlined loops would otherwise have names of
  // O(n) characters each, O(n^2) in all for the symbol tables, the linker and the hashing.
  llvm::StringRef owner = fn_->getName();
  owner = owner.take_front(std::min(owner.find(".loop"), owner.find(".c")));
  llvm::Function *bodyFn = makeBodyFunction(mc_, owner.str() + ".loop" + std::to_string(i), false);
  bodyFn->addFnAttr(llvm::Attribute::NoInline); // the point is a separate, small function
  mc_.pendingLoops.push_back({bodyFn, {i + 1, next}});

  Loop l = openLoop(i);
  llvm::BasicBlock *stop = newBlock("loop.stop");
  llvm::Value *status = b_.CreateCall(bodyFn, {state_}, "status");
  l.remaining->addIncoming(b_.Insert(llvm::BinaryOperator::CreateSub(l.remaining, b_.getInt32(1))),
                           b_.GetInsertBlock());
  b_.CreateCondBr(b_.CreateICmpNE(status, b_.getInt32(LJ_FAULT_NONE)), stop, l.header);
  b_.SetInsertPoint(stop);
  llvm::Value *isRetn = b_.CreateICmpEQ(status, b_.getInt32(kStatusReturn));
  b_.CreateRet(b_.CreateSelect(isRetn, b_.getInt32(retnStatus_), status));
  b_.SetInsertPoint(l.exit);
  st_.clear();
  ms_.clear();
}

llvm::Error FunctionEmitter::emitNext(int32_t i) {
  if (loops_.empty() || prog_.info[i].target != loops_.back().loopIndex)
    return fail(i, "LoopEnd does not close the innermost LoopBegin");
  Loop l = loops_.back();
  loops_.pop_back();
  cache_.flush();
  l.remaining->addIncoming(b_.Insert(llvm::BinaryOperator::CreateSub(l.remaining, b_.getInt32(1))),
                           b_.GetInsertBlock());
  b_.CreateBr(l.header);
  b_.SetInsertPoint(l.exit);
  st_.clear();
  ms_.clear();
  return llvm::Error::success();
}

llvm::Error FunctionEmitter::emitCall(int32_t i) {
  const StmtInfo &info = prog_.info[i];
  if (info.target < 0 || info.target >= static_cast<int32_t>(mc_.subFns.size()))
    return fail(i, "Call of an unknown subroutine");
  // The caller's ST/MS are compile-time values here, so they survive the call untouched.
  llvm::Value *en = enable();
  llvm::BasicBlock *cont = newBlock("after.call");
  cache_.flush();
  if (auto *c = llvm::dyn_cast<llvm::ConstantInt>(en); !(c && c->isOne())) {
    llvm::BasicBlock *doCall = newBlock("call");
    b_.CreateCondBr(en, doCall, cont);
    b_.SetInsertPoint(doCall);
  }
  llvm::Value *status = b_.CreateCall(mc_.subFns[info.target], {state_}, "status");
  llvm::BasicBlock *propagate = newBlock("call.fault");
  b_.CreateCondBr(b_.CreateICmpNE(status, b_.getInt32(LJ_FAULT_NONE)), propagate, cont);
  b_.SetInsertPoint(propagate);
  // A JumpOut the callee took goes on at its label when this CALL is one it can reach (the
  // sliced part, VerifiedProgram::callExits); anything else (a watchdog abort, a JumpOut for the
  // caller's caller) leaves this function with the same status.
  std::span<const std::pair<int32_t, int32_t>> exits = exitsOfCall(prog_, i);
  if (!exits.empty()) {
    llvm::BasicBlock *up = newBlock("call.up");
    llvm::SwitchInst *sw = b_.CreateSwitch(status, up, static_cast<unsigned>(exits.size()));
    for (const auto &[call, lbl] : exits) {
      llvm::BasicBlock *target = jumpTarget(lbl);
      if (!target) return fail(i, "the label of a JumpOut is outside the lowered body");
      llvm::BasicBlock *go = newBlock("call.jumpout");
      sw->addCase(
          b_.getInt32(kStatusJumpOut + static_cast<uint32_t>(prog_.stmts[lbl].ops[0].index)), go);
      b_.SetInsertPoint(go);
      if (lbl < i) // a backward jump counts one watchdog step, as a JMP does
        watchdogStep(target);
      else
        b_.CreateBr(target);
    }
    b_.SetInsertPoint(up);
  }
  b_.CreateRet(status); // a watchdog abort stops the whole tick
  b_.SetInsertPoint(cont);
  return llvm::Error::success();
}

llvm::Error FunctionEmitter::emitJumpOut(int32_t i) {
  if (prog_.info[i].target < 0 || prog_.stmts[prog_.info[i].target].op != Op::Label)
    return fail(i, "JumpOut target is not a Label");
  returnWhenEnabled(kStatusJumpOut +
                        static_cast<uint32_t>(prog_.stmts[prog_.info[i].target].ops[0].index),
                    "jumpout");
  return llvm::Error::success();
}

void FunctionEmitter::emitRetn() { returnWhenEnabled(retnStatus_, "retn"); }

void FunctionEmitter::returnWhenEnabled(uint32_t status, const char *name) {
  llvm::Value *en = enable();
  cache_.flush();
  llvm::BasicBlock *ret = newBlock(name);
  llvm::BasicBlock *cont = newBlock((std::string("no") + name).c_str());
  b_.CreateCondBr(en, ret, cont);
  b_.SetInsertPoint(ret);
  b_.CreateRet(b_.getInt32(status));
  b_.SetInsertPoint(cont);
}

} // namespace lj::lower
