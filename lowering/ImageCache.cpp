// The per-block state cache: loads on first use, one store per changed field at flush.
#include "lowering/ImageCache.h"

#include <cassert>

namespace lj::lower {

void ImageCache::dropOverlaps(const StateLoc &loc) {
  // Only byte-region locations (span > 0) overlap: drop every other entry sharing a byte with
  // [offset, offset + span) so its value is reloaded and its store is never deleted.
  const uint32_t lo = loc.offset >= 7 ? loc.offset - 7 : 0, hi = loc.offset + loc.span;
  for (auto it = entries_.lower_bound(lo); it != entries_.end() && it->first < hi;) {
    const StateLoc &e = it->second.loc;
    const uint32_t eEnd = e.offset + (e.span ? e.span : 8);
    const bool same = e.offset == loc.offset && e.type == loc.type;
    if (!same && e.span && eEnd > loc.offset)
      it = entries_.erase(it);
    else
      ++it;
  }
}

llvm::Value *ImageCache::load(const StateLoc &loc) {
  if (loc.span) dropOverlaps(loc);
  auto it = entries_.find(loc.offset);
  if (it != entries_.end()) {
    assert(it->second.loc.type == loc.type && "one type per state offset");
    return it->second.value;
  }
  llvm::Value *addr = layout_.address(b_, state_, loc);
  llvm::Value *v = loc.align ? b_.CreateAlignedLoad(loc.type, addr, llvm::Align(loc.align), loc.name)
                             : b_.CreateLoad(loc.type, addr, loc.name);
  entries_.emplace(loc.offset, Entry{loc, v, addr, nullptr});
  return v;
}

void ImageCache::store(const StateLoc &loc, llvm::Value *v) {
  assert(v->getType() == loc.type && "store of the field's own type");
  if (loc.span) dropOverlaps(loc);
  auto it = entries_.find(loc.offset);
  if (it == entries_.end())
    it = entries_.emplace(loc.offset, Entry{loc, v, layout_.address(b_, state_, loc), nullptr})
             .first;
  Entry &e = it->second;
  // The earlier store is dead: no load of this field can follow it in this block.
  if (e.lastStore) e.lastStore->eraseFromParent();
  e.value = v;
  e.lastStore = loc.align ? b_.CreateAlignedStore(v, e.addr, llvm::Align(loc.align))
                          : b_.CreateStore(v, e.addr);
}

void ImageCache::flush() { entries_.clear(); }

} // namespace lj::lower
