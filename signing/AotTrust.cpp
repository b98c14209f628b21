// Ed25519 keys for AOT .so files (signing/AotTrust.h): generation, PEM files with ownership and
// permission checks, signing and verification through OpenSSL's EVP interface.
#include "signing/AotTrust.h"

#include <openssl/bio.h>
#include <openssl/evp.h>
#include <openssl/pem.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>

namespace lj::signing {

struct SigningKey::Impl {
  EVP_PKEY *pkey = nullptr;
  ~Impl() { EVP_PKEY_free(pkey); }
};

namespace {

constexpr off_t kMaxKeyFile = 16 * 1024;

/// Refuse to prompt for a passphrase: keys are unencrypted files guarded by their mode.
int noPassphrase(char *, int, int, void *) { return 0; }

std::string bioText(BIO *bio) {
  char *data = nullptr;
  long n = BIO_get_mem_data(bio, &data);
  std::string out = n > 0 ? std::string(data, static_cast<size_t>(n)) : std::string();
  BIO_free(bio);
  return out;
}

/// Read a small key file after checking what it is and who may change it. `secret`: owner must
/// be the effective user and no group/other bits; else owner the user or root, no group/other
/// write bit.
bool readKeyFile(const std::string &path, bool secret, std::string &out, std::string &error) {
  int fd = open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK | O_NOCTTY);
  if (fd < 0) {
    error = "'" + path + "': cannot open: " + std::strerror(errno);
    return false;
  }
  struct stat st {};
  bool ok = fstat(fd, &st) == 0;
  const uid_t me = geteuid();
  if (!ok || !S_ISREG(st.st_mode)) {
    error = "'" + path + "': not a regular file";
    ok = false;
  } else if (st.st_size > kMaxKeyFile) {
    error = "'" + path + "': too large for a key file";
    ok = false;
  } else if (st.st_uid != me && (secret || st.st_uid != 0)) {
    error = "'" + path + "': owned by uid " + std::to_string(st.st_uid) +
            ", not by this user (uid " + std::to_string(me) + ")";
    ok = false;
  } else if ((st.st_mode & (secret ? 077 : 022)) != 0) {
    error = "'" + path + "': " +
            (secret ? "private key is accessible by group or others (chmod 600 it)"
                    : "public key is writable by group or others (chmod 644 it)");
    ok = false;
  }
  if (ok) {
    out.resize(static_cast<size_t>(st.st_size));
    ssize_t n = read(fd, out.data(), out.size());
    if (n != static_cast<ssize_t>(out.size())) {
      error = "'" + path + "': cannot read";
      ok = false;
    }
  }
  close(fd);
  return ok;
}

/// The directory holding the default keys must belong to this user and be closed to others.
bool checkDir(const std::string &dir, std::string &error) {
  struct stat st {};
  if (stat(dir.c_str(), &st) != 0) {
    error = "key directory '" + dir + "': " + std::strerror(errno);
    return false;
  }
  if (!S_ISDIR(st.st_mode)) {
    error = "key directory '" + dir + "': not a directory";
    return false;
  }
  if (st.st_uid != geteuid()) {
    error = "key directory '" + dir + "': owned by uid " + std::to_string(st.st_uid) +
            ", not by this user";
    return false;
  }
  if ((st.st_mode & 022) != 0) {
    error = "key directory '" + dir + "': writable by group or others (chmod 700 it)";
    return false;
  }
  return true;
}

/// mkdir -p with mode 0700 for every directory it creates.
bool makeDirs(const std::string &dir, std::string &error) {
  for (size_t pos = 1; pos <= dir.size(); ++pos) {
    if (pos != dir.size() && dir[pos] != '/') continue;
    std::string part = dir.substr(0, pos);
    if (mkdir(part.c_str(), 0700) != 0 && errno != EEXIST) {
      error = "cannot create key directory '" + part + "': " + std::strerror(errno);
      return false;
    }
  }
  return true;
}

/// A complete temp file next to `final` with `mode`; its name in `tmp`.
bool writeTemp(const std::string &final, const std::string &text, mode_t mode, std::string &tmp,
               std::string &error) {
  std::string templ = final + ".tmpXXXXXX";
  std::vector<char> buf(templ.begin(), templ.end());
  buf.push_back('\0');
  int fd = mkostemp(buf.data(), O_CLOEXEC);
  if (fd < 0) {
    error = "cannot create '" + templ + "': " + std::strerror(errno);
    return false;
  }
  tmp = buf.data();
  bool ok = fchmod(fd, mode) == 0 &&
            write(fd, text.data(), text.size()) == static_cast<ssize_t>(text.size()) &&
            fsync(fd) == 0;
  close(fd);
  if (!ok) {
    error = "cannot write '" + tmp + "'";
    unlink(tmp.c_str());
  }
  return ok;
}

} // namespace

SigningKey::SigningKey() = default;
SigningKey::~SigningKey() { delete key_; }
SigningKey::SigningKey(SigningKey &&o) noexcept : key_(o.key_) { o.key_ = nullptr; }
SigningKey &SigningKey::operator=(SigningKey &&o) noexcept {
  std::swap(key_, o.key_);
  return *this;
}

bool SigningKey::generate(std::string &error) {
  EVP_PKEY *k = EVP_PKEY_Q_keygen(nullptr, nullptr, "ED25519");
  if (!k) {
    error = "cannot generate an Ed25519 key (OpenSSL)";
    return false;
  }
  delete key_;
  key_ = new Impl{k};
  return true;
}

bool SigningKey::loadFile(const std::string &path, std::string &error) {
  std::string pem;
  if (!readKeyFile(path, true, pem, error)) return false;
  BIO *bio = BIO_new_mem_buf(pem.data(), static_cast<int>(pem.size()));
  EVP_PKEY *k = bio ? PEM_read_bio_PrivateKey(bio, nullptr, noPassphrase, nullptr) : nullptr;
  BIO_free(bio);
  if (!k || EVP_PKEY_get_id(k) != EVP_PKEY_ED25519) {
    EVP_PKEY_free(k);
    error = "'" + path +
            "': not an unencrypted Ed25519 private key PEM (make one with "
            "`ladderjit keygen`)";
    return false;
  }
  delete key_;
  key_ = new Impl{k};
  return true;
}

std::string SigningKey::publicRaw() const {
  std::string raw(kEd25519KeySize, '\0');
  size_t n = raw.size();
  if (!key_ ||
      EVP_PKEY_get_raw_public_key(key_->pkey, reinterpret_cast<unsigned char *>(raw.data()), &n) !=
          1 ||
      n != kEd25519KeySize)
    return {};
  return raw;
}

bool SigningKey::sign(std::string_view message, std::string &signature, std::string &error) const {
  signature.assign(kEd25519SigSize, '\0');
  size_t n = signature.size();
  EVP_MD_CTX *ctx = EVP_MD_CTX_new();
  bool ok = key_ && ctx && EVP_DigestSignInit(ctx, nullptr, nullptr, nullptr, key_->pkey) == 1 &&
            EVP_DigestSign(ctx, reinterpret_cast<unsigned char *>(signature.data()), &n,
                           reinterpret_cast<const unsigned char *>(message.data()),
                           message.size()) == 1 &&
            n == kEd25519SigSize;
  EVP_MD_CTX_free(ctx);
  if (!ok) error = "cannot sign (OpenSSL)";
  return ok;
}

std::string SigningKey::privatePem() const {
  BIO *bio = BIO_new(BIO_s_mem());
  if (!bio || !key_) return {};
  PEM_write_bio_PrivateKey(bio, key_->pkey, nullptr, nullptr, 0, nullptr, nullptr);
  return bioText(bio);
}

std::string SigningKey::publicPem() const {
  BIO *bio = BIO_new(BIO_s_mem());
  if (!bio || !key_) return {};
  PEM_write_bio_PUBKEY(bio, key_->pkey);
  return bioText(bio);
}

std::string keyId(std::string_view raw) {
  static const char *kHex = "0123456789abcdef";
  std::string out = "ed25519:";
  for (unsigned char c : raw) {
    out += kHex[c >> 4];
    out += kHex[c & 15];
  }
  return out;
}

bool TrustedKeys::addFile(const std::string &path, std::string &error) {
  std::string pem;
  if (!readKeyFile(path, false, pem, error)) return false;
  BIO *bio = BIO_new_mem_buf(pem.data(), static_cast<int>(pem.size()));
  EVP_PKEY *k = bio ? PEM_read_bio_PUBKEY(bio, nullptr, noPassphrase, nullptr) : nullptr;
  BIO_free(bio);
  std::string raw(kEd25519KeySize, '\0');
  size_t n = raw.size();
  bool ok =
      k && EVP_PKEY_get_id(k) == EVP_PKEY_ED25519 &&
      EVP_PKEY_get_raw_public_key(k, reinterpret_cast<unsigned char *>(raw.data()), &n) == 1 &&
      n == kEd25519KeySize;
  EVP_PKEY_free(k);
  if (!ok) {
    error = "'" + path + "': not an Ed25519 public key PEM (`ladderjit keygen` writes NAME.pub)";
    return false;
  }
  keys_.push_back(std::move(raw));
  return true;
}

bool TrustedKeys::trusts(std::string_view raw) const {
  for (const std::string &k : keys_)
    if (k == raw) return true;
  return false;
}

bool TrustedKeys::verify(std::string_view raw, std::string_view message,
                         std::string_view signature) {
  if (raw.size() != kEd25519KeySize || signature.size() != kEd25519SigSize) return false;
  EVP_PKEY *k = EVP_PKEY_new_raw_public_key(
      EVP_PKEY_ED25519, nullptr, reinterpret_cast<const unsigned char *>(raw.data()), raw.size());
  EVP_MD_CTX *ctx = EVP_MD_CTX_new();
  bool ok = k && ctx && EVP_DigestVerifyInit(ctx, nullptr, nullptr, nullptr, k) == 1 &&
            EVP_DigestVerify(
                ctx, reinterpret_cast<const unsigned char *>(signature.data()), signature.size(),
                reinterpret_cast<const unsigned char *>(message.data()), message.size()) == 1;
  EVP_MD_CTX_free(ctx);
  EVP_PKEY_free(k);
  return ok;
}

std::string defaultKeyDir(std::string &error) {
  if (const char *d = std::getenv("LADDERJIT_KEY_DIR"); d && *d) return d;
  if (const char *x = std::getenv("XDG_CONFIG_HOME"); x && *x) return std::string(x) + "/ladderjit";
  if (const char *h = std::getenv("HOME"); h && *h) return std::string(h) + "/.config/ladderjit";
  error = "no key directory: set LADDERJIT_KEY_DIR (or HOME)";
  return {};
}

bool writeKeyPair(const SigningKey &key, const std::string &base, std::string &error) {
  const std::string priv = base + ".key", pub = base + ".pub";
  struct stat st {};
  for (const std::string &p : {priv, pub})
    if (lstat(p.c_str(), &st) == 0) {
      error = "'" + p + "' already exists (refusing to overwrite a key)";
      return false;
    }
  std::string tmpPriv, tmpPub;
  if (!writeTemp(priv, key.privatePem(), 0600, tmpPriv, error)) return false;
  if (!writeTemp(pub, key.publicPem(), 0644, tmpPub, error)) {
    unlink(tmpPriv.c_str());
    return false;
  }
  // link() never replaces an existing name (nor follows a planted symlink at it).
  bool ok = true;
  if (link(tmpPriv.c_str(), priv.c_str()) != 0) {
    error = "cannot create '" + priv + "': " + std::strerror(errno);
    ok = false;
  } else if (link(tmpPub.c_str(), pub.c_str()) != 0) {
    error = "cannot create '" + pub + "': " + std::strerror(errno);
    unlink(priv.c_str());
    ok = false;
  }
  unlink(tmpPriv.c_str());
  unlink(tmpPub.c_str());
  return ok;
}

bool defaultSigningKey(SigningKey &key, std::string &path, bool &created, std::string &error) {
  created = false;
  std::string dir = defaultKeyDir(error);
  if (dir.empty()) return false;
  path = dir + "/" + kDefaultKeyName + ".key";
  struct stat st {};
  if (stat(dir.c_str(), &st) != 0 && !makeDirs(dir, error)) return false;
  if (!checkDir(dir, error)) return false;
  if (lstat(path.c_str(), &st) != 0 && errno == ENOENT) {
    SigningKey fresh;
    if (!fresh.generate(error)) return false;
    std::string werr;
    if (writeKeyPair(fresh, dir + "/" + kDefaultKeyName, werr)) {
      key = std::move(fresh);
      created = true;
      return true;
    }
    if (lstat(path.c_str(), &st) != 0) { // not a lost race with another compile
      error = werr;
      return false;
    }
  }
  return key.loadFile(path, error);
}

bool loadTrustedKeys(const std::vector<std::string> &files, TrustedKeys &keys, std::string &error) {
  for (const std::string &f : files)
    if (!keys.addFile(f, error)) return false;
  if (!files.empty()) return true;
  std::string dir = defaultKeyDir(error);
  if (dir.empty()) return false;
  const std::string pub = dir + "/" + kDefaultKeyName + ".pub";
  struct stat st {};
  if (stat(pub.c_str(), &st) != 0) {
    error = "no trusted AOT signing key: '" + pub +
            "' does not exist; give --trust-key FILE.pub, or build the .so on this account with "
            "`ladderjit compile` (which creates that default key pair)";
    return false;
  }
  if (!checkDir(dir, error)) return false;
  return keys.addFile(pub, error);
}

} // namespace lj::signing
