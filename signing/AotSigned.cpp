// Building and verifying the signed trailer of an AOT .so (signing/AotSigned.h). Parsing is strict
// and bounded: every field exactly once, decimal numbers without signs, fixed-size footer.
#include "signing/AotSigned.h"

#include "ladderjit/program.h"

#include <charconv>
#include <cstdio>
#include <map>

namespace lj::signing {

namespace {

constexpr size_t kMagicLen = sizeof(LJPROG_META_MAGIC) - 1;
constexpr size_t kFooterMagicLen = sizeof(LJPROG_FOOTER_MAGIC) - 1;
static_assert(kFooterMagicLen + 8 + 1 == LJPROG_FOOTER_SIZE);
static_assert(LJPROG_SIG_SIZE == kEd25519SigSize);

constexpr const char *kFields[] = {"abi",    "program",    "source",     "plc2_nvalue",
                                   "slices", "state_size", "image_size", "key"};

bool isHash(std::string_view h) {
  if (h.size() != 71 || h.substr(0, 7) != "sha256:") return false;
  for (char c : h.substr(7))
    if (!((c >= '0' && c <= '9') || (c >= 'a' && c <= 'f'))) return false;
  return true;
}

template <typename T> bool number(std::string_view text, T &out) {
  if (text.empty() || text.size() > 20 || text[0] < '0' || text[0] > '9') return false;
  auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), out);
  return ec == std::errc() && end == text.data() + text.size();
}

bool unhex(std::string_view hex, std::string &out) {
  out.clear();
  if (hex.size() % 2) return false;
  auto val = [](char c) {
    return c >= '0' && c <= '9' ? c - '0' : c >= 'a' && c <= 'f' ? c - 'a' + 10 : -1;
  };
  for (size_t i = 0; i < hex.size(); i += 2) {
    int hi = val(hex[i]), lo = val(hex[i + 1]);
    if (hi < 0 || lo < 0) return false;
    out += static_cast<char>(hi * 16 + lo);
  }
  return true;
}

/// Parse META text into `m`; the reason on failure.
std::string parseMeta(std::string_view text, AotMeta &m) {
  if (text.substr(0, kMagicLen) != LJPROG_META_MAGIC) return "bad signed trailer header";
  std::map<std::string, std::string, std::less<>> kv;
  text.remove_prefix(kMagicLen);
  while (!text.empty()) {
    size_t nl = text.find('\n');
    if (nl == std::string_view::npos) return "bad signed trailer (unterminated line)";
    std::string_view line = text.substr(0, nl);
    text.remove_prefix(nl + 1);
    size_t eq = line.find(" = ");
    if (eq == std::string_view::npos) return "bad signed trailer line";
    std::string key(line.substr(0, eq));
    bool known = false;
    for (const char *f : kFields) known = known || key == f;
    if (!known || !kv.emplace(key, std::string(line.substr(eq + 3))).second)
      return "bad signed trailer field '" + key.substr(0, 32) + "'";
  }
  if (kv.size() != std::size(kFields)) return "signed trailer lacks a field";
  std::string keyHex = kv["key"];
  if (!isHash(kv["program"]) || !isHash(kv["source"]) || !number(kv["abi"], m.abi) ||
      !number(kv["plc2_nvalue"], m.plc2Nvalue) || !number(kv["slices"], m.slices) ||
      !number(kv["state_size"], m.stateSize) || !number(kv["image_size"], m.imageSize) ||
      keyHex.compare(0, 8, "ed25519:") != 0 || !unhex(keyHex.substr(8), m.key) ||
      m.key.size() != kEd25519KeySize)
    return "bad value in the signed trailer";
  m.program = kv["program"];
  m.source = kv["source"];
  return {};
}

} // namespace

bool signImage(std::string &file, AotMeta meta, const SigningKey &key, std::string &error) {
  meta.imageSize = file.size();
  meta.key = key.publicRaw();
  std::string text = LJPROG_META_MAGIC;
  text += "abi = " + std::to_string(meta.abi) + "\n";
  text += "program = " + meta.program + "\n";
  text += "source = " + meta.source + "\n";
  text += "plc2_nvalue = " + std::to_string(meta.plc2Nvalue) + "\n";
  text += "slices = " + std::to_string(meta.slices) + "\n";
  text += "state_size = " + std::to_string(meta.stateSize) + "\n";
  text += "image_size = " + std::to_string(meta.imageSize) + "\n";
  text += "key = " + keyId(meta.key) + "\n";
  if (text.size() > LJPROG_META_MAX || meta.key.size() != kEd25519KeySize) {
    error = "cannot build the signed trailer";
    return false;
  }
  char footer[LJPROG_FOOTER_SIZE + 1];
  std::snprintf(footer, sizeof footer, "%s%08zx\n", LJPROG_FOOTER_MAGIC, text.size());
  file += text;
  file.append(footer, LJPROG_FOOTER_SIZE);
  std::string sig;
  if (!key.sign(file, sig, error)) return false;
  file += sig;
  return true;
}

std::string verifySigned(std::string_view file, const TrustedKeys &trust, AotMeta &meta) {
  const std::string_view kNoTrailer =
      "no ladderjit signature at the end (truncated, built by an older ladderjit, or not built "
      "by `ladderjit compile`)";
  if (file.size() < LJPROG_TRAILER_MIN) return std::string(kNoTrailer);
  std::string_view signedPart = file.substr(0, file.size() - LJPROG_SIG_SIZE);
  std::string_view sig = file.substr(signedPart.size());
  std::string_view footer = signedPart.substr(signedPart.size() - LJPROG_FOOTER_SIZE);
  if (footer.substr(0, kFooterMagicLen) != LJPROG_FOOTER_MAGIC || footer.back() != '\n')
    return std::string(kNoTrailer);
  size_t metaLen = 0;
  std::string_view lenHex = footer.substr(kFooterMagicLen, 8);
  for (char c : lenHex) {
    int v = c >= '0' && c <= '9' ? c - '0' : c >= 'a' && c <= 'f' ? c - 'a' + 10 : -1;
    if (v < 0) return "bad signature trailer footer";
    metaLen = metaLen * 16 + static_cast<size_t>(v);
  }
  if (metaLen > LJPROG_META_MAX || metaLen > signedPart.size() - LJPROG_FOOTER_SIZE)
    return "bad signature trailer footer (truncated?)";
  const size_t imageSize = signedPart.size() - LJPROG_FOOTER_SIZE - metaLen;
  AotMeta m;
  if (std::string why = parseMeta(signedPart.substr(imageSize, metaLen), m); !why.empty())
    return why;
  // The signer's key is named in META (not yet trusted text): it only selects which trusted key
  // to verify with, so an unknown key gets a precise message.
  if (!trust.trusts(m.key))
    return "signed by " + keyId(m.key) +
           ", which is not a trusted key (see --trust-key; docs/aot.md \"Trust\")";
  if (!TrustedKeys::verify(m.key, signedPart, sig))
    return "bad signature: the file was modified after `ladderjit compile` signed it";
  if (m.imageSize != imageSize) return "signed trailer does not match the file layout";
  meta = std::move(m);
  return {};
}

} // namespace lj::signing
