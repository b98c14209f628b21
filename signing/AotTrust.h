// Who may produce an AOT .so that run/serve load (docs/aot.md "Trust"): Ed25519 signing keys
// (`ladderjit keygen`, `compile --sign-key`), the public keys run/serve trust (`--trust-key`),
// and the default per-user key pair in $LADDERJIT_KEY_DIR or ~/.config/ladderjit. OpenSSL EVP.
#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace lj::signing {

/// Length of a raw Ed25519 public key and of a signature.
constexpr size_t kEd25519KeySize = 32;
constexpr size_t kEd25519SigSize = 64;

/// An Ed25519 private key (move-only).
class SigningKey {
public:
  SigningKey();
  ~SigningKey();
  SigningKey(SigningKey &&) noexcept;
  SigningKey &operator=(SigningKey &&) noexcept;

  /// A fresh key pair. False + `error` when OpenSSL fails.
  bool generate(std::string &error);
  /// Read a private key PEM (`ladderjit keygen`). The file must be a regular file of the
  /// effective user with no group/other permission bits (like ssh); false + `error` otherwise.
  bool loadFile(const std::string &path, std::string &error);
  bool valid() const { return key_ != nullptr; }

  /// The 32-byte raw public key.
  std::string publicRaw() const;
  /// Signature of `message` (64 bytes). False + `error` on an OpenSSL failure.
  bool sign(std::string_view message, std::string &signature, std::string &error) const;
  /// PEM texts: PKCS#8 private key, SubjectPublicKeyInfo public key.
  std::string privatePem() const;
  std::string publicPem() const;

private:
  struct Impl;
  Impl *key_ = nullptr;
};

/// "ed25519:" + 64 lowercase hex digits of a raw public key: how keys are named in messages and
/// in a .so's signed trailer.
std::string keyId(std::string_view raw);

/// The public keys whose signatures run/serve accept.
class TrustedKeys {
public:
  /// Add the public key PEM at `path`: a regular file of the effective user or root, not
  /// writable by group or others, at most 16 KiB, holding an Ed25519 key.
  bool addFile(const std::string &path, std::string &error);
  void addRaw(std::string raw) { keys_.push_back(std::move(raw)); }
  bool trusts(std::string_view raw) const;
  bool empty() const { return keys_.empty(); }
  /// Whether `signature` is a valid Ed25519 signature of `message` by the raw key `raw` (which
  /// the caller has found trusted).
  static bool verify(std::string_view raw, std::string_view message, std::string_view signature);

private:
  std::vector<std::string> keys_;
};

/// The default key directory: $LADDERJIT_KEY_DIR, else $XDG_CONFIG_HOME/ladderjit, else
/// $HOME/.config/ladderjit. Empty with `error` when none of them is set.
std::string defaultKeyDir(std::string &error);
/// Base name of the default key pair in that directory (`.key` private, `.pub` public).
constexpr const char *kDefaultKeyName = "aot-signing";

/// Write a key pair to `base`.key (mode 0600) and `base`.pub (0644). Refuses to overwrite or to
/// follow a symlink; false + `error` naming the file.
bool writeKeyPair(const SigningKey &key, const std::string &base, std::string &error);

/// The signing key `compile` uses without --sign-key: the default pair, created (directory
/// 0700) when missing. `created` tells whether it was made now, `path` names the private key.
/// Refuses a directory or key file owned by another user or writable by group/others.
bool defaultSigningKey(SigningKey &key, std::string &path, bool &created, std::string &error);

/// The keys run/serve trust: every file of `files` (--trust-key), or, when none is given, the
/// default public key (which must exist and pass the same ownership checks).
bool loadTrustedKeys(const std::vector<std::string> &files, TrustedKeys &keys, std::string &error);

} // namespace lj::signing
