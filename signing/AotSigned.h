// The signed trailer of an AOT .so (runtime_abi/include/ladderjit/program.h, docs/aot.md
// "Trust"): `compile` appends it, the loader verifies it before mapping any byte of the file.
#pragma once

#include "signing/AotTrust.h"

#include <cstdint>
#include <string>
#include <string_view>

namespace lj::signing {

/// What the trailer states about the image; everything the loader checks comes from here.
struct AotMeta {
  uint32_t abi = 0;       ///< LJPROG_ABI_VERSION of the build
  std::string program;    ///< program hash "sha256:..." (docs/aot.md "Program hash")
  std::string source;     ///< the same without the nvalue (engines/AotLoader.h sourceHash)
  int32_t plc2Nvalue = 0; ///< the nvalue the slicing was compiled with
  uint32_t slices = 0;    ///< PLC2 slices of the entry table
  uint64_t stateSize = 0; ///< sizeof(lj_state) of the build
  uint64_t imageSize = 0; ///< bytes of the ELF image before the trailer
  std::string key;        ///< raw Ed25519 public key of the signer (32 bytes)
};

/// Append META, FOOTER and the signature by `key` to the ELF image in `file`. `meta.imageSize`
/// and `meta.key` are filled in here. False + `error` on a signing failure.
bool signImage(std::string &file, AotMeta meta, const SigningKey &key, std::string &error);

/// Check `file`'s trailer: layout, a signer in `trust`, a valid signature over every byte before
/// it. Empty on success (then `meta` holds the signed facts and `meta.imageSize` bytes of `file`
/// are the image); else the reason, one line.
std::string verifySigned(std::string_view file, const TrustedKeys &trust, AotMeta &meta);

} // namespace lj::signing
