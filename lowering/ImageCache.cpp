// The per-block state cache: loads on first use, one store per changed field at flush.
#include "lowering/ImageCache.h"

#include <cassert>

namespace lj::lower {

llvm::Value *ImageCache::load(const StateLoc &loc) {
  auto it = entries_.find(loc.offset);
  if (it != entries_.end()) {
    assert(it->second.loc.type == loc.type && "one type per state offset");
    return it->second.value;
  }
  llvm::Value *addr = layout_.address(b_, state_, loc);
  llvm::Value *v = b_.CreateLoad(loc.type, addr, loc.name);
  entries_.emplace(loc.offset, Entry{loc, v, addr, nullptr});
  return v;
}

void ImageCache::store(const StateLoc &loc, llvm::Value *v) {
  assert(v->getType() == loc.type && "store of the field's own type");
  auto it = entries_.find(loc.offset);
  if (it == entries_.end())
    it = entries_.emplace(loc.offset, Entry{loc, v, layout_.address(b_, state_, loc), nullptr})
             .first;
  Entry &e = it->second;
  // The earlier store is dead: no load of this field can follow it in this block.
  if (e.lastStore) e.lastStore->eraseFromParent();
  e.value = v;
  e.lastStore = b_.CreateStore(v, e.addr);
}

void ImageCache::flush() { entries_.clear(); }

} // namespace lj::lower
