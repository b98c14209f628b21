// Assembles the module of one program: a function per subroutine, the init / PLC1 entries, one
// function per PLC2 slice behind the lj_plc2 switch, and long bodies cut into chunk functions.
#include "lowering/EdgeImage.h"
#include "lowering/FunctionEmitter.h"
#include "lowering/Lower.h"

#include "ir/SyncInputs.h"

#include "ladderjit/abi.h"

#include <llvm/ADT/STLExtras.h>
#include <llvm/IR/Verifier.h>
#include <llvm/Support/raw_ostream.h>

#include <algorithm>
#include <unordered_map>

namespace lj::lower {

namespace {

enum class FnKind { Entry, SliceEntry, Body, CarriedBody };

// Attributes promised for the state pointer: it is the only way generated code reaches memory,
// so LLVM may keep image bytes in registers and merge stores.
void markStateParam(llvm::Function *fn, unsigned argNo) {
  llvm::AttrBuilder ab(fn->getContext());
  ab.addAttribute(llvm::Attribute::NoAlias);
  ab.addAttribute(llvm::Attribute::NoCapture);
  ab.addAttribute(llvm::Attribute::NonNull);
  ab.addAttribute(llvm::Attribute::NoUndef);
  ab.addAlignmentAttr(llvm::Align(8));
  ab.addDereferenceableAttr(StateLayout::stateSize());
  fn->addParamAttrs(argNo, ab);
  fn->getArg(argNo)->setName("s");
}

llvm::Function *makeFunction(llvm::Module &m, const std::string &name, FnKind kind,
                             bool shared = false) {
  llvm::LLVMContext &ctx = m.getContext();
  llvm::Type *i32 = llvm::Type::getInt32Ty(ctx);
  llvm::Type *ptr = llvm::PointerType::getUnqual(ctx);
  std::vector<llvm::Type *> params;
  if (kind == FnKind::Body) params = {ptr};
  if (kind == FnKind::CarriedBody) params = {ptr, ptr};
  if (kind == FnKind::Entry) params = {ptr, ptr};
  if (kind == FnKind::SliceEntry) params = {ptr, ptr, i32};
  // `shared`: a body another partition's module may call, so it must be visible to the linker.
  auto linkage = kind == FnKind::Body && !shared ? llvm::GlobalValue::InternalLinkage
                                                 : llvm::GlobalValue::ExternalLinkage;
  llvm::Function *fn =
      llvm::Function::Create(llvm::FunctionType::get(i32, params, false), linkage, name, m);
  fn->addFnAttr(llvm::Attribute::NoUnwind);
  if (shared) fn->setDSOLocal(true); // the partitions are linked together: direct calls, no PLT
  if (kind == FnKind::CarriedBody) {
    markStateParam(fn, 0);
    fn->addParamAttr(1, llvm::Attribute::NoAlias);
    fn->addParamAttr(1, llvm::Attribute::NoCapture);
    fn->getArg(1)->setName("carry");
    return fn;
  }
  markStateParam(fn, kind == FnKind::Body ? 0 : 1);
  if (kind != FnKind::Body) {
    fn->getArg(0)->setName("ctx"); // the engine context; compiled code does not use it
    if (kind == FnKind::SliceEntry) fn->getArg(2)->setName("slice");
  }
  return fn;
}

// A leaf of a spine by its symbol: equal leaves (equal keys) occur more than once in a program.
llvm::Function *declareLeaf(llvm::Module &m, const std::string &symbol, bool carried) {
  if (llvm::Function *f = m.getFunction(symbol)) return f;
  return makeFunction(m, symbol, carried ? FnKind::CarriedBody : FnKind::Body, true);
}

llvm::Value *stateArg(llvm::Function *fn) { return fn->getArg(fn->arg_size() == 1 ? 0 : 1); }

/// The carry buffer of a cut body, at `b` (its driver's entry): the live entries at carried cuts
/// (zeroed: dead entries read as 0). No buffer (null) when no cut is carried.
CarryBuffer carryBuffer(ModuleContext &mc, llvm::IRBuilder<> &b,
                        const std::vector<ChunkPlan> &chunks) {
  int32_t stMax = 0, msMax = 0;
  bool carried = false;
  for (const ChunkPlan &c : chunks) {
    if (!c.carriedOut) continue;
    carried = true;
    stMax = std::max(stMax, mc.prog.info[c.r.end].depth);
    msMax = std::max(msMax, mc.prog.info[c.r.end].msDepth);
  }
  CarryBuffer carry;
  if (carried) {
    const uint64_t size = static_cast<uint64_t>(std::max(stMax + msMax, 1));
    carry.buf = b.CreateAlloca(llvm::ArrayType::get(b.getInt8Ty(), size), nullptr, "carry");
    carry.msBase = stMax;
    b.CreateMemSet(carry.buf, b.getInt8(0), size, llvm::MaybeAlign(1));
  }
  return carry;
}

/// The return of a cut body's driver at `b` (its stop block): the status a chunk returned, where
/// in a subroutine's own function a RETN (kStatusReturn) ends it normally with `retnStatus`.
void returnStatus(llvm::IRBuilder<> &b, llvm::Value *status, bool isSub, uint32_t retnStatus) {
  if (isSub && retnStatus != kStatusReturn)
    status = b.CreateSelect(b.CreateICmpEQ(status, b.getInt32(kStatusReturn)),
                            b.getInt32(retnStatus), status);
  b.CreateRet(status);
}

/// What LowerOptions::mergeIr / mergeStores / mergeIndexed bound in one function.
struct FunctionSize {
  int64_t ir = 0, stores = 0, indexed = 0;
};

FunctionSize functionSize(const llvm::Function &f) {
  FunctionSize z;
  for (const llvm::BasicBlock &bb : f)
    for (const llvm::Instruction &inst : bb) {
      ++z.ir;
      z.stores += llvm::isa<llvm::StoreInst>(inst);
      const llvm::Value *p = llvm::getLoadStorePointerOperand(&inst);
      if (p && !llvm::isa<llvm::Argument, llvm::AllocaInst>(p->stripInBoundsConstantOffsets()))
        ++z.indexed; // an address computed at run time (a table, an indexed operand)
    }
  return z;
}

// lowerBody's chunks (a body without JMP spans cut) emitted into as few functions as
// LowerOptions::mergeIr / mergeStores / mergeIndexed allow: each function `fn.c<k>` takes
// consecutive chunks through one emitter until it reaches any of the bounds or a carried cut
// (whose live entries go through the carry buffer, as lowerBody hands them on); `fn` calls
// them in order and stops at a non-zero status.
llvm::Error lowerMergedChunks(ModuleContext &mc, llvm::Function *fn,
                              const std::vector<ChunkPlan> &chunks, int32_t deadDepth, bool isSub,
                              uint32_t retnStatus) {
  llvm::LLVMContext &ctx = fn->getContext();
  llvm::IRBuilder<> b(llvm::BasicBlock::Create(ctx, "entry", fn));
  const CarryBuffer carry = carryBuffer(mc, b, chunks);
  const bool carried = carry.buf != nullptr;
  const uint32_t chunkRetn = isSub ? kStatusReturn : retnStatus;
  std::vector<llvm::Function *> parts;
  llvm::Function *cur = nullptr;
  std::unique_ptr<FunctionEmitter> fe;
  CarryBuffer mine;
  for (size_t k = 0; k < chunks.size(); ++k) {
    const ChunkPlan &c = chunks[k];
    if (!cur) {
      cur =
          makeBodyFunction(mc, fn->getName().str() + ".c" + std::to_string(parts.size()), carried);
      cur->addFnAttr(llvm::Attribute::NoInline);
      fe = std::make_unique<FunctionEmitter>(mc, cur, cur->getArg(0), chunkRetn);
      mine = CarryBuffer{carried ? cur->getArg(1) : nullptr, carry.msBase, nullptr};
    }
    const int32_t dead = k == 0 ? deadDepth : mc.prog.info[c.r.begin].depth;
    if (llvm::Error e = fe->emitRange(c.r, dead, &c, &mine)) return e;
    const FunctionSize z = functionSize(*cur);
    if (k + 1 == chunks.size() || c.carriedOut || z.ir >= mc.opts.mergeIr ||
        z.stores >= mc.opts.mergeStores || z.indexed >= mc.opts.mergeIndexed) {
      if (llvm::Error e = fe->finish()) return e;
      parts.push_back(cur);
      cur = nullptr;
    }
  }
  llvm::BasicBlock *stop = llvm::BasicBlock::Create(ctx, "stop", fn);
  llvm::PHINode *status = llvm::PHINode::Create(b.getInt32Ty(), parts.size(), "status", stop);
  for (llvm::Function *part : parts) {
    llvm::Value *st = carried ? b.CreateCall(part, {stateArg(fn), carry.buf}, "st")
                              : b.CreateCall(part, {stateArg(fn)}, "st");
    llvm::BasicBlock *next = llvm::BasicBlock::Create(ctx, "next", fn);
    status->addIncoming(st, b.GetInsertBlock());
    b.CreateCondBr(b.CreateICmpNE(st, b.getInt32(0)), stop, next);
    b.SetInsertPoint(next);
  }
  b.CreateRet(b.getInt32(LJ_FAULT_NONE));
  b.SetInsertPoint(stop);
  returnStatus(b, status, isSub, retnStatus);
  return llvm::Error::success();
}

// Lowers one body (a part, a slice, a subroutine or an outlined loop body) into `fn`, cutting it
// into chunk functions when it is long. `retnStatus` is what a taken RETN returns from `fn`: 0
// from a subroutine's own function, kStatusReturn from an outlined loop body; in a chunk of a
// subroutine (`isSub`) a RETN returns kStatusReturn, which becomes `retnStatus` here.
// With `namer` (the spine of an incremental compile) every chunk, and a short body as a whole,
// is a leaf: declared under the name `namer` gives it and called, its code lowered elsewhere.
llvm::Error lowerBody(ModuleContext &mc, llvm::Function *fn, StmtRange r, int32_t deadDepth,
                      bool isSub, uint32_t retnStatus = LJ_FAULT_NONE,
                      const LeafNamer *namer = nullptr) {
  std::vector<ChunkPlan> chunks =
      planChunkFunctions(mc.prog, r, mc.opts.chunkStatements, &mc.weightBefore);
  if (chunks.size() <= 1 && namer) {
    Leaf leaf;
    leaf.r = r;
    leaf.deadDepth = deadDepth;
    leaf.retnStatus = retnStatus;
    llvm::Function *lf = declareLeaf(mc.mod, (*namer)(leaf), false);
    llvm::IRBuilder<> b(llvm::BasicBlock::Create(fn->getContext(), "entry", fn));
    b.CreateRet(b.CreateCall(lf, {stateArg(fn)}));
    return llvm::Error::success();
  }
  if (chunks.size() <= 1) {
    FunctionEmitter fe(mc, fn, stateArg(fn), retnStatus);
    if (llvm::Error e = fe.emitRange(r, deadDepth)) return e;
    return fe.finish();
  }
  if (!namer && !chunks.front().jumps && mc.opts.mergeIr > 0)
    return lowerMergedChunks(mc, fn, chunks, deadDepth, isSub, retnStatus);
  llvm::LLVMContext &ctx = fn->getContext();
  llvm::IRBuilder<> b(llvm::BasicBlock::Create(ctx, "entry", fn));
  const CarryBuffer carry = carryBuffer(mc, b, chunks);
  const bool carried = carry.buf != nullptr;
  // Chunk k runs in block chunk<k>; a non-zero status goes to `stop`, or with jumps between
  // chunks first to `dispatch`, which goes on at the chunk a kStatusJump names.
  const bool jumps = chunks.front().jumps;
  auto labelChunkOwned = std::make_shared<LabelChunks>();
  LabelChunks &labelChunk = *labelChunkOwned;
  std::vector<llvm::BasicBlock *> callAt;
  for (size_t k = 0; k < chunks.size(); ++k) {
    callAt.push_back(llvm::BasicBlock::Create(ctx, "chunk" + std::to_string(k), fn));
    if (jumps && mc.prog.stmts[chunks[k].r.begin].op == Op::Label)
      labelChunk[chunks[k].r.begin] = static_cast<uint32_t>(k);
  }
  b.CreateBr(callAt[0]);
  llvm::BasicBlock *done = llvm::BasicBlock::Create(ctx, "done", fn);
  llvm::IRBuilder<>(done).CreateRet(b.getInt32(LJ_FAULT_NONE));
  llvm::BasicBlock *stop = llvm::BasicBlock::Create(ctx, "stop", fn);
  llvm::PHINode *stopStatus = llvm::PHINode::Create(b.getInt32Ty(), chunks.size(), "status", stop);
  llvm::BasicBlock *dispatch = stop;
  llvm::PHINode *jumpStatus = nullptr;
  if (jumps) {
    dispatch = llvm::BasicBlock::Create(ctx, "dispatch", fn);
    llvm::IRBuilder<> db(dispatch);
    jumpStatus = db.CreatePHI(b.getInt32Ty(), chunks.size(), "status");
    llvm::SwitchInst *sw = db.CreateSwitch(jumpStatus, stop, labelChunk.size());
    for (auto &[lbl, k] : labelChunk) sw->addCase(db.getInt32(kStatusJump + k), callAt[k]);
    stopStatus->addIncoming(jumpStatus, dispatch);
  }
  for (size_t k = 0; k < chunks.size(); ++k) {
    const ChunkPlan &c = chunks[k];
    b.SetInsertPoint(callAt[k]);
    const uint32_t chunkRetn = isSub ? kStatusReturn : retnStatus;
    int32_t dead = k == 0 ? deadDepth : mc.prog.info[c.r.begin].depth;
    llvm::Function *cfn = nullptr;
    if (namer) {
      Leaf leaf;
      leaf.r = c.r;
      leaf.deadDepth = dead;
      leaf.retnStatus = chunkRetn;
      leaf.chunk = true;
      leaf.plan = c;
      leaf.carried = carried;
      leaf.msBase = carry.msBase;
      if (jumps) leaf.labelChunk = labelChunkOwned;
      cfn = declareLeaf(mc.mod, (*namer)(leaf), carried);
    } else {
      cfn = makeBodyFunction(mc, fn->getName().str() + ".c" + std::to_string(k), carried);
      cfn->addFnAttr(llvm::Attribute::NoInline); // keep functions small: linear compile time
      FunctionEmitter fe(mc, cfn, cfn->getArg(0), chunkRetn);
      const CarryBuffer mine{carried ? cfn->getArg(1) : nullptr, carry.msBase,
                             jumps ? &labelChunk : nullptr};
      if (llvm::Error e = fe.emitRange(c.r, dead, &c, &mine)) return e;
      if (llvm::Error e = fe.finish()) return e;
    }
    llvm::Value *st = carried ? b.CreateCall(cfn, {stateArg(fn), carry.buf}, "st")
                              : b.CreateCall(cfn, {stateArg(fn)}, "st");
    b.CreateCondBr(b.CreateICmpNE(st, b.getInt32(0)), dispatch,
                   k + 1 < chunks.size() ? callAt[k + 1] : done);
    (jumps ? jumpStatus : stopStatus)->addIncoming(st, callAt[k]);
  }
  b.SetInsertPoint(stop);
  returnStatus(b, stopStatus, isSub, retnStatus);
  return llvm::Error::success();
}

// lowerBody, then the loop bodies it outlined (and theirs), without recursion.
llvm::Error lowerTopBody(ModuleContext &mc, llvm::Function *fn, StmtRange r, int32_t deadDepth,
                         bool isSub, const LeafNamer *namer = nullptr) {
  if (llvm::Error e = lowerBody(mc, fn, r, deadDepth, isSub, LJ_FAULT_NONE, namer)) return e;
  while (!mc.pendingLoops.empty()) {
    ModuleContext::Outlined o = mc.pendingLoops.back();
    mc.pendingLoops.pop_back();
    // A RETN in the body (only in a subroutine) reaches the LOOP's function as kStatusReturn.
    if (llvm::Error e = lowerBody(mc, o.fn, o.body, 0, true, kStatusReturn)) return e;
  }
  return llvm::Error::success();
}

void emitSliceSwitch(const VerifiedProgram &prog, llvm::Function *plc2,
                     const std::vector<llvm::Function *> &slices) {
  llvm::LLVMContext &ctx = plc2->getContext();
  llvm::IRBuilder<> b(llvm::BasicBlock::Create(ctx, "entry", plc2));
  llvm::BasicBlock *none = llvm::BasicBlock::Create(ctx, "no.slice", plc2);
  llvm::SwitchInst *sw = b.CreateSwitch(plc2->getArg(2), none, slices.size());
  for (size_t k = 0; k < slices.size(); ++k) {
    llvm::BasicBlock *bb = llvm::BasicBlock::Create(ctx, "slice" + std::to_string(k), plc2);
    sw->addCase(b.getInt32(static_cast<uint32_t>(k)), bb);
    b.SetInsertPoint(bb);
    if (k == 0 && latchesSyncInputs(prog)) {
      // A scan of the divided sliced part starts: latch the inputs its statements read from
      // the synchronized input memory (FANUC level 2, ir/Profile.h SyncInputs).
      const TargetProfile::SyncInputs &m = prog.profile->syncInputs;
      llvm::Value *s = stateArg(plc2);
      b.CreateMemCpy(b.CreateConstInBoundsGEP1_64(b.getInt8Ty(), s, m.copy), llvm::MaybeAlign(1),
                     b.CreateConstInBoundsGEP1_64(b.getInt8Ty(), s, m.from), llvm::MaybeAlign(1),
                     m.bytes);
    }
    b.CreateRet(b.CreateCall(slices[k], {stateArg(plc2)}));
  }
  b.SetInsertPoint(none);
  b.CreateRet(b.getInt32(LJ_FAULT_NONE)); // lj_tick never asks for a slice that does not exist
}

} // namespace

llvm::Function *makeBodyFunction(ModuleContext &mc, const std::string &name, bool carried) {
  return makeFunction(mc.mod, name, carried ? FnKind::CarriedBody : FnKind::Body);
}

std::vector<uint32_t> planPartitions(const VerifiedProgram &prog, uint32_t partitions) {
  std::vector<int64_t> weight;
  for (const Subroutine &sub : prog.subs) weight.push_back(sub.body.end - sub.body.begin);
  weight.push_back(prog.init.end - prog.init.begin);
  weight.push_back(prog.plc1.end - prog.plc1.begin);
  if (prog.slices.empty()) weight.push_back(prog.plc2.end - prog.plc2.begin);
  for (const StmtRange &r : prog.slices) weight.push_back(r.end - r.begin);
  int64_t total = 0;
  for (int64_t &w : weight) total += (w += 1); // +1: even an empty body costs a function
  std::vector<uint32_t> owner;
  int64_t before = 0;
  const int64_t parts = std::max<uint32_t>(partitions, 1);
  for (int64_t w : weight) {
    // The partition holding the unit's midpoint: contiguous groups of about total/parts.
    owner.push_back(
        static_cast<uint32_t>(std::min(parts - 1, (2 * before + w) * parts / (2 * total))));
    before += w;
  }
  return owner;
}

namespace {

/// The module of lowerProgram, or with `namer` the spine of lowerSpine.
llvm::Expected<std::unique_ptr<llvm::Module>>
lowerModule(const VerifiedProgram &prog, llvm::LLVMContext &ctx, const llvm::DataLayout &dl,
            const std::string &triple, const LowerOptions &opts, const LeafNamer *namer) {
  auto mod = std::make_unique<llvm::Module>(prog.file.empty() ? "program" : prog.file, ctx);
  mod->setDataLayout(dl);
  mod->setTargetTriple(triple);
  llvm::Expected<StateLayout> layout = StateLayout::create(ctx, dl, opts.readableNames);
  if (!layout) return layout.takeError();
  if (prog.info.size() != prog.stmts.size())
    return llvm::createStringError("verified program without statement facts");
  ModuleContext mc{prog, *mod, *layout, opts, {}, {}, {0}, {}, {}};
  if (opts.forces) mc.forced = forceTable(prog, *opts.forces);
  if (opts.trace) mc.traceAt = traceLayout(prog);
  for (int32_t i = 0; i < static_cast<int32_t>(prog.stmts.size()); ++i)
    mc.weightBefore.push_back(mc.weightBefore.back() + bodyWeight(prog, {i, i + 1}));
  const uint32_t parts = std::max<uint32_t>(opts.partitions, 1);
  const bool shared = parts > 1 || namer; // leaves of the spine call the subroutines
  const std::vector<uint32_t> owner = planPartitions(prog, parts);
  size_t unit = 0; // index into `owner`
  auto mine = [&](size_t u) { return owner[u] == opts.partition; };

  for (const Subroutine &sub : prog.subs)
    mc.subFns.push_back(
        makeFunction(*mod, "lj_sub" + std::to_string(sub.number), FnKind::Body, shared));
  for (size_t k = 0; k < prog.subs.size(); ++k, ++unit)
    if (mine(unit))
      if (llvm::Error e = lowerTopBody(mc, mc.subFns[k], prog.subs[k].body, 0, true, namer))
        return e;

  if (mine(unit++)) {
    llvm::Function *init = makeFunction(*mod, kInitSymbol, FnKind::Entry);
    if (llvm::Error e = lowerTopBody(mc, init, prog.init, 0, false, namer)) return e;
  }
  if (mine(unit++)) {
    llvm::Function *plc1 = makeFunction(*mod, kPlc1Symbol, FnKind::Entry);
    if (hasEdgeImage(prog)) { // EdgePolicy::PerObject: the body, then the edge image
      llvm::Function *body = makeFunction(*mod, "lj_plc1.body", FnKind::Entry);
      body->setLinkage(llvm::GlobalValue::InternalLinkage);
      if (llvm::Error e = lowerTopBody(mc, body, prog.plc1, 0, false, namer)) return e;
      emitEdgeImageEntry(mc, plc1, body);
    } else if (llvm::Error e = lowerTopBody(mc, plc1, prog.plc1, 0, false, namer)) {
      return e;
    }
  }

  std::vector<StmtRange> slices = prog.slices;
  if (slices.empty()) slices.push_back(prog.plc2);
  std::vector<llvm::Function *> sliceFns;
  for (size_t k = 0; k < slices.size(); ++k, ++unit) {
    llvm::Function *fn =
        makeFunction(*mod, "lj_plc2.s" + std::to_string(k), FnKind::Body, parts > 1);
    sliceFns.push_back(fn);
    if (!mine(unit)) continue; // declared only: another partition defines it
    // In a spine the slice function only calls its leaf (or dispatches its chunks): the spine
    // is compiled with inlining of these, one function for the switch instead of one per slice.
    fn->addFnAttr(namer ? llvm::Attribute::AlwaysInline : llvm::Attribute::NoInline);
    int32_t dead = k < prog.sliceDepth.size() ? prog.sliceDepth[k] : 0;
    if (llvm::Error e = lowerTopBody(mc, fn, slices[k], dead, false, namer)) return e;
  }
  if (opts.partition == 0)
    emitSliceSwitch(prog, makeFunction(*mod, kPlc2Symbol, FnKind::SliceEntry), sliceFns);
  // Declarations nobody here calls would only be noise in the object's symbol table.
  for (llvm::Function &f : llvm::make_early_inc_range(*mod))
    if (f.isDeclaration() && f.use_empty() && !f.isIntrinsic()) f.eraseFromParent();

  std::string msg;
  llvm::raw_string_ostream os(msg);
  if (llvm::verifyModule(*mod, &os))
    return llvm::createStringError("internal error: lowered module is invalid: %s", msg.c_str());
  return mod;
}

} // namespace

llvm::Expected<std::unique_ptr<llvm::Module>>
lowerProgram(const VerifiedProgram &prog, llvm::LLVMContext &ctx, const llvm::DataLayout &dl,
             const std::string &triple, const LowerOptions &opts) {
  return lowerModule(prog, ctx, dl, triple, opts, nullptr);
}

llvm::Expected<std::unique_ptr<llvm::Module>>
lowerSpine(const VerifiedProgram &prog, llvm::LLVMContext &ctx, const llvm::DataLayout &dl,
           const std::string &triple, const LowerOptions &opts, const LeafNamer &namer) {
  if (opts.partitions > 1) return llvm::createStringError("a spine is never partitioned");
  return lowerModule(prog, ctx, dl, triple, opts, &namer);
}

llvm::Expected<std::unique_ptr<llvm::Module>>
lowerLeaf(const VerifiedProgram &prog, const Leaf &leaf, const std::string &symbol,
          llvm::LLVMContext &ctx, const llvm::DataLayout &dl, const std::string &triple,
          const LowerOptions &opts) {
  auto mod = std::make_unique<llvm::Module>(symbol, ctx);
  mod->setDataLayout(dl);
  mod->setTargetTriple(triple);
  llvm::Expected<StateLayout> layout = StateLayout::create(ctx, dl, opts.readableNames);
  if (!layout) return layout.takeError();
  if (prog.info.size() != prog.stmts.size() || leaf.r.begin < 0 || leaf.r.begin > leaf.r.end ||
      leaf.r.end > static_cast<int32_t>(prog.stmts.size()))
    return llvm::createStringError("leaf outside the verified program");
  ModuleContext mc{prog, *mod, *layout, opts, {},
                   {},   {},   {},      {}}; // leaves are never traced (Session::compile)
  if (opts.forces) mc.forced = forceTable(prog, *opts.forces);
  // Only differences of weights inside the leaf are read (loop sizes, nested chunk plans).
  mc.weightBefore.assign(static_cast<size_t>(leaf.r.begin) + 1, 0);
  for (int32_t i = leaf.r.begin; i < leaf.r.end; ++i)
    mc.weightBefore.push_back(mc.weightBefore.back() + bodyWeight(prog, {i, i + 1}));
  mc.weightBefore.resize(prog.stmts.size() + 1, mc.weightBefore.back());
  for (const Subroutine &sub : prog.subs)
    mc.subFns.push_back(
        makeFunction(*mod, "lj_sub" + std::to_string(sub.number), FnKind::Body, true));
  llvm::Function *fn =
      makeFunction(*mod, symbol, leaf.carried ? FnKind::CarriedBody : FnKind::Body, true);
  FunctionEmitter fe(mc, fn, fn->getArg(0), leaf.retnStatus);
  if (leaf.chunk) {
    const CarryBuffer mine{leaf.carried ? fn->getArg(1) : nullptr, leaf.msBase,
                           leaf.labelChunk.get()};
    if (llvm::Error e = fe.emitRange(leaf.r, leaf.deadDepth, &leaf.plan, &mine)) return e;
  } else if (llvm::Error e = fe.emitRange(leaf.r, leaf.deadDepth)) {
    return e;
  }
  if (llvm::Error e = fe.finish()) return e;
  while (!mc.pendingLoops.empty()) {
    ModuleContext::Outlined o = mc.pendingLoops.back();
    mc.pendingLoops.pop_back();
    if (llvm::Error e = lowerBody(mc, o.fn, o.body, 0, true, kStatusReturn)) return e;
  }
  for (llvm::Function &f : llvm::make_early_inc_range(*mod))
    if (f.isDeclaration() && f.use_empty() && !f.isIntrinsic()) f.eraseFromParent();
  std::string msg;
  llvm::raw_string_ostream os(msg);
  if (llvm::verifyModule(*mod, &os))
    return llvm::createStringError("internal error: lowered leaf is invalid: %s", msg.c_str());
  return mod;
}

} // namespace lj::lower
