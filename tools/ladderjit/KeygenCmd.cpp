// `ladderjit keygen -o DIR/NAME`: a new Ed25519 key pair for signing AOT .so files (docs/aot.md
// "Trust"): NAME.key (private, mode 0600) for `compile --sign-key`, NAME.pub for `--trust-key`.
#include "tools/ladderjit/Commands.h"

#include "signing/AotTrust.h"

#include <cstdio>

namespace lj::cli {

int runKeygen(const KeygenArgs &a) {
  if (a.output.empty()) return usageError("keygen: -o DIR/NAME is empty");
  signing::SigningKey key;
  std::string error;
  if (!key.generate(error) || !signing::writeKeyPair(key, a.output, error))
    return usageError("keygen: " + error);
  std::printf("%s.key: private key (keep it secret; `ladderjit compile --sign-key`)\n"
              "%s.pub: public key %s (`run`/`serve --trust-key`)\n",
              a.output.c_str(), a.output.c_str(), signing::keyId(key.publicRaw()).c_str());
  return std::fflush(stdout) == 0 && !std::ferror(stdout) ? kOk : kUsage;
}

} // namespace lj::cli
