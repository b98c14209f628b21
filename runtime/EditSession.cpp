// The ladder editor's server side (runtime/EditSession.h, docs/ladder-edit.md).
#include "runtime/EditSession.h"

#include "formats/InputFiles.h"
#include "formats/PlcDit.h"
#include "ir/OpTable.h"
#include "ladder/Json.h"
#include "ladder/Network.h"
#include "pipeline/Dialects.h"
#include "services/HttpServer.h"

#include <dirent.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <regex>
#include <set>

namespace lj::rt {

using nlohmann::json;

namespace {

constexpr size_t kMaxEditorName = 64;
constexpr size_t kMaxDiagnostics = 200;
constexpr off_t kAuditMaxBytes = off_t{4} << 20;    // then the log moves to .1 (one kept)
constexpr size_t kAuditMaxDiff = size_t{256} << 10; // a record's diff is cut beyond this

std::string utcNow() {
  const std::time_t t = std::time(nullptr);
  std::tm tm{};
  gmtime_r(&t, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return buf;
}

std::string baseName(const std::string &p) {
  const size_t s = p.rfind('/');
  return s == std::string::npos ? p : p.substr(s + 1);
}

std::string dirName(const std::string &p) {
  const size_t s = p.rfind('/');
  return s == std::string::npos ? "." : s == 0 ? "/" : p.substr(0, s);
}

/// The extension of `p`'s file name with its dot (".stl"), empty when none.
std::string extension(const std::string &p) {
  const std::string b = baseName(p);
  const size_t d = b.rfind('.');
  return d == std::string::npos || d == 0 ? std::string() : b.substr(d);
}

bool endsWith(const std::string &s, const char *tail) {
  const size_t n = std::strlen(tail);
  return s.size() >= n && s.compare(s.size() - n, n, tail) == 0;
}

std::string errnoText(const std::string &what) { return what + ": " + std::strerror(errno); }

bool writeAll(int fd, const std::string &data) {
  size_t off = 0;
  while (off < data.size()) {
    const ssize_t n = ::write(fd, data.data() + off, data.size() - off);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    off += static_cast<size_t>(n);
  }
  return true;
}

bool syncDir(const std::string &dir, std::string &error) {
  const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0 || ::fsync(fd) != 0) {
    error = errnoText("cannot sync the directory '" + dir + "'");
    if (fd >= 0) ::close(fd);
    return false;
  }
  ::close(fd);
  return true;
}

/// `data` into the new file `fd` (`path`, opened by the caller; -1: it could not be made) with
/// `mode`, synced and closed; removed again when that failed.
bool fillNew(int fd, const std::string &path, const std::string &data, mode_t mode,
             std::string &error) {
  if (fd < 0) {
    error = errnoText("cannot create '" + path + "'");
    return false;
  }
  const bool ok = ::fchmod(fd, mode) == 0 && writeAll(fd, data) && ::fsync(fd) == 0;
  if (!ok) error = errnoText("cannot write '" + path + "'");
  ::close(fd);
  if (!ok) ::unlink(path.c_str());
  return ok;
}

/// The next free number in the history folder `dir` (0001, 0002, ...), the folder made (0700).
bool nextHistory(const std::string &dir, const std::string &ext, std::string &out,
                 std::string &error) {
  if (::mkdir(dir.c_str(), 0700) != 0 && errno != EEXIST) {
    error = errnoText("cannot make the history folder '" + dir + "'");
    return false;
  }
  struct stat st {};
  if (::lstat(dir.c_str(), &st) != 0 || !S_ISDIR(st.st_mode)) {
    error = "'" + dir + "' is not a directory (the history folder of the program)";
    return false;
  }
  long last = 0;
  if (DIR *d = ::opendir(dir.c_str())) {
    while (dirent *e = ::readdir(d)) {
      char *end = nullptr;
      const long n = std::strtol(e->d_name, &end, 10);
      if (end != e->d_name && n > last) last = n;
    }
    ::closedir(d);
  }
  char num[32];
  std::snprintf(num, sizeof num, "%04ld", last + 1);
  out = dir + "/" + num + ext;
  return true;
}

/// The new content of the program file `path`, written before the online change: `data` in a
/// temporary file beside it (the file's mode), synced. False with `error` (nothing left behind)
/// when the directory does not take it, so the change is not made.
bool prepareProgram(const std::string &path, const std::string &data, std::string &temp,
                    std::string &error) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0 || !S_ISREG(st.st_mode)) {
    error = "'" + path + "' is no longer a regular file";
    return false;
  }
  temp = dirName(path) + "/." + baseName(path) + ".edit-XXXXXX";
  return fillNew(::mkstemp(temp.data()), temp, data, st.st_mode & 07777, error);
}

/// After the online change: the old content `old` kept as the next numbered copy in the history
/// folder (`historyFile`), then the prepared `temp` renamed over `path` and the directory synced.
bool commitProgram(const std::string &path, const std::string &temp, const std::string &old,
                   std::string &historyFile, std::string &error) {
  struct stat st {};
  const mode_t mode = ::stat(path.c_str(), &st) == 0 ? st.st_mode & 07777 : 0600;
  const std::string hdir = EditSession::historyDir(path);
  if (!nextHistory(hdir, extension(path), historyFile, error)) return false;
  const int hfd =
      ::open(historyFile.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0600);
  if (!fillNew(hfd, historyFile, old, mode & 0700 ? mode : 0600, error) || !syncDir(hdir, error))
    return false;
  if (::rename(temp.c_str(), path.c_str()) != 0) {
    error = errnoText("cannot rename '" + temp + "' to '" + path + "'");
    return false;
  }
  return syncDir(dirName(path), error);
}

/// One JSON line appended to the audit log (moved to `.1` once larger than kAuditMaxBytes).
bool appendAudit(const std::string &file, const json &record, std::string &error) {
  struct stat st {};
  if (::stat(file.c_str(), &st) == 0 && st.st_size > kAuditMaxBytes &&
      ::rename(file.c_str(), (file + ".1").c_str()) != 0) {
    error = errnoText("cannot rotate '" + file + "'");
    return false;
  }
  const int fd = ::open(file.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_NOFOLLOW | O_CLOEXEC, 0600);
  if (fd < 0) {
    error = errnoText("cannot open '" + file + "'");
    return false;
  }
  const std::string line = record.dump(-1, ' ', false, json::error_handler_t::replace) + "\n";
  const bool ok = writeAll(fd, line) && ::fsync(fd) == 0;
  if (!ok) error = errnoText("cannot write '" + file + "'");
  ::close(fd);
  return ok;
}

std::vector<std::string> splitLines(const std::string &s) {
  std::vector<std::string> out;
  size_t p = 0;
  while (p < s.size()) {
    size_t nl = s.find('\n', p);
    if (nl == std::string::npos) nl = s.size();
    out.push_back(s.substr(p, nl - p));
    p = nl + 1;
  }
  return out;
}

/// "PLC1 rung 3 element 2" in `text`: the part, rung and element it names.
void placeOf(const std::string &text, json &d) {
  static const std::regex re(R"((\S+) rung (\d+)(?: element (\d+))?)");
  std::smatch m;
  if (!std::regex_search(text, m, re)) return;
  d["part"] = m[1].str();
  d["rung"] = std::stoi(m[2].str());
  if (m[3].matched) d["element"] = std::stoi(m[3].str());
}

/// The verifier's rendered diagnostics ("FILE:LINE:COL: error: MESSAGE") as JSON objects, each
/// mapped through `origins` (one per line of the program text) to part, rung, element and id.
json mapDiagnostics(const std::string &rendered, const std::vector<ladder::LineOrigin> *origins) {
  static const std::regex re(R"(^.*?:(\d+):(\d+): (error|warning): (.*)$)");
  json out = json::array();
  for (const std::string &l : splitLines(rendered)) {
    std::smatch m;
    json d;
    if (std::regex_match(l, m, re)) {
      d = {{"severity", m[3].str()},
           {"message", m[4].str()},
           {"line", std::stoi(m[1].str())},
           {"column", std::stoi(m[2].str())}};
      const auto line = static_cast<size_t>(std::stoi(m[1].str()));
      if (origins && line >= 1 && line <= origins->size() && !(*origins)[line - 1].where.empty()) {
        d["where"] = (*origins)[line - 1].where;
        d["id"] = (*origins)[line - 1].id;
      }
      placeOf(d.contains("where") ? d["where"].get<std::string>() : m[4].str(), d);
    } else if (l.find(": error: ") != std::string::npos) {
      d = {{"severity", "error"}, {"message", l.substr(l.find(": error: ") + 9)}};
      placeOf(l, d);
    } else {
      continue; // notes, the numbered text made from the networks
    }
    out.push_back(std::move(d));
    if (out.size() >= kMaxDiagnostics) break;
  }
  return out;
}

/// A refusal with its reason.
EditAnswer refusal(unsigned status, const std::string &why, json extra = json::object()) {
  extra["ok"] = false;
  extra["error"] = why;
  return {status, std::move(extra)};
}

/// What a running version is, for editing.
struct Served {
  std::shared_ptr<ProgramVersion> cur;
  std::string path;
  std::string text;        ///< the file's bytes (the running version's, `fresh`)
  bool fresh = false;      ///< the file still holds the running version
  bool json = false;       ///< a `.json` ladder PROGRAM
  std::string notEditable; ///< why it cannot be edited live, empty when it can
};

Served served(Executive &exec, Controller &ctl) {
  Served s;
  s.cur = exec.current();
  std::string so;
  s.path = ctl.programPath(&so);
  if (!s.cur) {
    s.notEditable = "no program is running yet";
    return s;
  }
  if (!so.empty() || !s.cur->so.empty()) {
    s.notEditable = "this server runs an AOT .so (serve --engine aot:...): a compiled .so cannot "
                    "be edited live; edit the program text, `ladderjit compile` it and `monitor "
                    "load` the new .so";
    return s;
  }
  std::string err;
  if (!formats::readFile(s.path, s.text, err)) {
    s.notEditable = "cannot read the served program: " + err;
    return s;
  }
  s.fresh = formats::sha256Hash(s.text) == s.cur->hash;
  s.json = endsWith(s.path, ".json");
  if (!s.json && (endsWith(s.path, ".dit") || formats::looksLikeDit(s.text)))
    s.notEditable = "the served PROGRAM is a plc.dit container, which the HNC-8 tools write "
                    "(hash line, sections): it is not edited live; serve its STL to edit it";
  else if (s.cur->prog && !s.cur->prog->grids.empty())
    s.notEditable = "the served PROGRAM is a ClassicLadder project, whose rungs are its editor's "
                    "grid (docs/classicladder.md): edit it in ClassicLadder and save it; the file "
                    "watch (or `monitor load`) takes the new version";
  return s;
}

/// The running version's network JSON (what `ladderjit ladder --format json` writes for it).
json runningNetworks(const Served &s) {
  if (!s.cur || !s.cur->prog) return nullptr;
  if (s.json && s.fresh) {
    json j = json::parse(s.text, nullptr, false);
    if (!j.is_discarded()) return j;
  }
  const bool hnc8 = s.cur->prog->profile && pipeline::dialectNamed(s.cur->prog->profile->name) ==
                                                &pipeline::defaultDialect();
  std::string text = ladder::writeJson(ladder::fromProgram(*s.cur->prog),
                                       hnc8 || !s.fresh ? std::string_view() : s.text);
  json j = json::parse(text, nullptr, false);
  return j.is_discarded() ? json(nullptr) : j;
}

/// What an update does with the init part (docs/ladder-edit.md "The init part").
json initJson(const VerifiedProgram &p) {
  const std::string dialect = p.profile ? p.profile->name : "";
  std::vector<std::string> writes;
  std::set<std::string> seen;
  for (auto i = static_cast<size_t>(p.init.begin); i < static_cast<size_t>(p.init.end); ++i) {
    const Stmt &st = p.stmts[i];
    const InstrInfo &info = instrInfo(st.op);
    for (uint8_t k = 0; k < st.operandCount && k < kMaxOperands; ++k)
      if (info.operands[k].writes && p.dialect && p.dialect->formatOperand) {
        std::string a = p.dialect->formatOperand(st.ops[k]);
        if (seen.insert(a).second) writes.push_back(a);
      }
  }
  const bool hasInit = p.init.end > p.init.begin;
  // The rule per dialect (docs/ladder-edit.md "The init part"): an update is the online change
  // `monitor load` makes, whose swap runs the new version's init part (docs/serve.md "The swap").
  std::string rule;
  if (dialect == "hnc8")
    rule = "an update is a program reload: the new init part runs once, in the tick the new "
           "version starts (hnc8-core.md 2.2: 重新载入PLC会运行一次初始化), as for `monitor load`; "
           "the image, timers and counters are kept";
  else if (dialect == "fanuc")
    rule = "the FANUC reference does not say what an online edit does to the first-scan relay; "
           "here an update is the online change `monitor load` makes: the init part ladderjit "
           "generates runs once in the swap tick, R9015.0 (first scan) is not set again, the "
           "image, timers and counters are kept";
  else
    rule = "the Neza reference describes cold and warm restarts only (%S0 / %S1, L581-582); an "
           "update is not a restart: %S0, %S1 and %S13 stay 0, the init part ladderjit generates "
           "(the %TMi.P / %Ci.P presets) runs once in the swap tick, the image, timers and "
           "counters are kept";
  return {{"runsOnUpdate", hasInit}, {"writes", writes}, {"rule", rule}};
}

/// The program file's new bytes made from the draft, and the origin of each of its lines
/// (a text PROGRAM). False with the answer (400 / 409 / 422) in `bad`.
bool makeBytes(const Served &s, const json &networks, std::string &bytes,
               std::vector<ladder::LineOrigin> &origins, EditAnswer &bad) {
  const DialectText *d = s.cur->prog->dialect;
  if (!d) {
    bad = refusal(409, "the running program has no dialect text to edit");
    return false;
  }
  ladder::Networks nets;
  std::string err;
  if (!ladder::readJson(networks.dump(), nets, err, *d)) {
    json diag = {{"severity", "error"}, {"message", err}};
    placeOf(err, diag);
    bad = refusal(422, "the draft is not a network JSON of this program's dialect: " + err,
                  {{"diagnostics", json::array({diag})}});
    return false;
  }
  if (s.json) {
    // The draft is the new file, written as `ladderjit ladder --format json` writes it (with
    // the program text a FANUC / IEC JSON carries) and read back as any `.json` PROGRAM.
    bytes = ladder::writeJson(nets, nets.source);
    return true;
  }
  // Untouched rungs byte for byte from the running file, the edited ones printed by the
  // dialect (ladder::programText), as a `.json` PROGRAM of another dialect is read.
  if (!ladder::programText(nets, *s.cur->prog, s.text, bytes, err, false, &origins)) {
    json diag = {{"severity", "error"}, {"message", err}};
    placeOf(err, diag);
    static const std::regex idRe(R"(\(id (-?\d+)\))");
    std::smatch m;
    if (std::regex_search(err, m, idRe)) diag["id"] = std::stoi(m[1].str());
    bad = refusal(422, err, {{"diagnostics", json::array({diag})}});
    return false;
  }
  return true;
}

} // namespace

std::string EditSession::auditPath(const std::string &path) { return path + ".edits.jsonl"; }
std::string EditSession::historyDir(const std::string &path) { return path + ".history"; }

EditSession::EditSession(Executive &exec, Controller &ctl, Log log)
    : exec_(exec), ctl_(ctl), log_(std::move(log)) {}

EditAnswer EditSession::status() {
  Served s = served(exec_, ctl_);
  json r{{"ok", true}};
  r["running"] = {{"version", s.cur ? s.cur->id : 0},
                  {"hash", s.cur ? s.cur->hash : ""},
                  {"file", s.path},
                  {"editable", s.notEditable.empty()},
                  {"networks", runningNetworks(s)}};
  if (!s.notEditable.empty()) r["running"]["why"] = s.notEditable;
  if (s.cur && !s.fresh && s.notEditable.empty())
    r["running"]["fileChanged"] = "the file on disk differs from the running version (the file "
                                  "watch loads it once it is stable)";
  if (s.cur && s.cur->prog) r["init"] = initJson(*s.cur->prog);
  r["files"] = {{"history", historyDir(s.path)}, {"audit", auditPath(s.path)}};
  std::lock_guard<std::mutex> g(mu_);
  if (draft_)
    r["draft"] = {{"open", true},
                  {"editor", draft_->editor},
                  {"client", draft_->client},
                  {"since", draft_->since},
                  {"base", draft_->base},
                  {"stale", !s.cur || s.cur->hash != draft_->base},
                  {"networks", draft_->networks}};
  else
    r["draft"] = {{"open", false}};
  return {200, std::move(r)};
}

EditAnswer EditSession::post(const std::string &action, const json &body,
                             const std::string &client) {
  // The editor: the page's own name for itself (one per browser tab), else the client address.
  std::string editor;
  if (body.contains("editor")) {
    if (!body["editor"].is_string() || body["editor"].get<std::string>().empty() ||
        body["editor"].get<std::string>().size() > kMaxEditorName)
      return refusal(400, "\"editor\" must be a string of 1 to " + std::to_string(kMaxEditorName) +
                              " characters");
    editor = body["editor"].get<std::string>();
    for (char c : editor)
      if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_' && c != '.')
        return refusal(400, "\"editor\" may hold letters, digits, '-', '_' and '.' only");
  } else {
    editor = client.substr(0, client.rfind(':'));
  }
  if (action == "draft") return draft(body, editor, client);
  for (const auto &[k, v] : body.items())
    if (k != "editor" && !(action == "update" && k == "removeParts"))
      return refusal(400, "unknown field '" + services::clientText(k) + "' in /api/edit/" + action +
                              " (it takes only \"editor\"" +
                              (action == "update" ? " and \"removeParts\"" : "") +
                              "; the draft is the one stored)");
  if (action == "check") return check(editor);
  if (action == "update") {
    // The parts the draft removes (列表编辑: a deleted or renamed subroutine), named by the
    // operator: an update that loses a part the running program has goes ahead only then.
    std::vector<std::string> removes;
    if (body.contains("removeParts")) {
      if (!body["removeParts"].is_array())
        return refusal(400, "\"removeParts\" must be an array of part names");
      for (const json &n : body["removeParts"]) {
        if (!n.is_string() || n.get<std::string>().empty() || n.get<std::string>().size() > 64)
          return refusal(400, "\"removeParts\" must be an array of part names");
        removes.push_back(n.get<std::string>());
      }
    }
    return update(editor, client, removes);
  }
  if (action == "discard") return discard(editor, client);
  return refusal(404, "no such edit action");
}

std::optional<EditAnswer> EditSession::heldByOther(const std::string &editor) const {
  if (!draft_ || draft_->editor == editor) return std::nullopt;
  return refusal(
      409,
      "a draft is open by editor '" + draft_->editor + "' (" + draft_->client + ") since " +
          draft_->since + "; send \"takeOver\": true with a draft to take it over",
      {{"reason", "held"},
       {"holder",
        {{"editor", draft_->editor}, {"client", draft_->client}, {"since", draft_->since}}}});
}

std::optional<EditAnswer> EditSession::notHeldBy(const std::string &editor) const {
  if (!draft_)
    return refusal(409, "no draft is open (POST /api/edit/draft first)", {{"reason", "no-draft"}});
  return heldByOther(editor);
}

EditAnswer EditSession::draft(const json &body, const std::string &editor,
                              const std::string &client) {
  static const std::regex hashRe("sha256:[0-9a-f]{64}");
  if (!body.contains("base") || !body["base"].is_string() ||
      !std::regex_match(body["base"].get<std::string>(), hashRe))
    return refusal(400, "a draft needs \"base\": the hash of the running version it was made from "
                        "(GET /api/edit, running.hash: \"sha256:\" and 64 hex digits)");
  if (body.contains("takeOver") && !body["takeOver"].is_boolean())
    return refusal(400, "\"takeOver\" must be true or false");
  json nets = body;
  nets.erase("base");
  nets.erase("editor");
  nets.erase("takeOver");
  if (!nets.contains("parts"))
    return refusal(400, "a draft is the program's network JSON (`ladderjit ladder --format json`, "
                        "GET /api/edit running.networks) with \"base\"; this one has no \"parts\"");
  Served s = served(exec_, ctl_);
  if (!s.notEditable.empty()) return refusal(409, s.notEditable, {{"reason", "not-editable"}});
  std::lock_guard<std::mutex> g(mu_);
  std::string took;
  if (std::optional<EditAnswer> held = heldByOther(editor)) {
    if (!body.value("takeOver", false)) return *held;
    took = " (took over the draft of editor '" + draft_->editor + "', " + draft_->client + ")";
  }
  const bool first = !draft_ || !took.empty();
  Draft d{editor, client, first ? utcNow() : draft_->since, body["base"].get<std::string>(),
          std::move(nets)};
  draft_ = std::move(d);
  if (log_)
    log_("edit: draft " + std::string(first ? "opened" : "saved") + " by editor '" + editor +
         "' from " + client + ", base " + draft_->base + took);
  json r{{"ok", true},
         {"since", draft_->since},
         {"base", draft_->base},
         {"stale", !s.cur || s.cur->hash != draft_->base}};
  return {200, std::move(r)};
}

EditAnswer EditSession::check(const std::string &editor) {
  std::lock_guard<std::mutex> g(mu_);
  if (std::optional<EditAnswer> no = notHeldBy(editor)) return *no;
  Served s = served(exec_, ctl_);
  if (!s.notEditable.empty()) return refusal(409, s.notEditable, {{"reason", "not-editable"}});
  std::string bytes, diagnostics;
  std::vector<ladder::LineOrigin> origins;
  EditAnswer bad;
  if (!makeBytes(s, draft_->networks, bytes, origins, bad)) return bad;
  std::optional<VerifiedProgram> p = ctl_.verifyEdit(s.path, bytes, diagnostics);
  json diags = mapDiagnostics(diagnostics, s.json ? nullptr : &origins);
  if (!p) return refusal(422, "the draft does not verify", {{"diagnostics", diags}});
  return {200,
          {{"ok", true},
           {"diagnostics", diags},
           {"removes",
            s.cur && s.cur->prog ? removedParts(*s.cur->prog, *p) : std::vector<std::string>{}},
           {"stale", !s.cur || s.cur->hash != draft_->base},
           {"diff",
            unifiedDiff(s.text, bytes, "running/" + baseName(s.path), "draft/" + baseName(s.path))},
           {"init", initJson(*p)}}};
}

EditAnswer EditSession::update(const std::string &editor, const std::string &client,
                               std::vector<std::string> removes) {
  std::lock_guard<std::mutex> g(mu_);
  if (std::optional<EditAnswer> no = notHeldBy(editor)) return *no;
  Served s = served(exec_, ctl_);
  if (!s.notEditable.empty()) return refusal(409, s.notEditable, {{"reason", "not-editable"}});
  auto stale = [&](const std::string &running) {
    if (log_)
      log_("edit: update by editor '" + editor + "' from " + client + " refused: its base " +
           draft_->base + " no longer runs (" + running + " does)");
    return refusal(409,
                   "the draft was made from " + draft_->base + ", but " + running +
                       " runs now (another client, monitor load or the file watch changed it); "
                       "nothing was merged: start a new draft from the running version",
                   {{"reason", "stale"},
                    {"base", draft_->base},
                    {"running", {{"hash", running}, {"networks", runningNetworks(s)}}}});
  };
  if (!s.cur || s.cur->hash != draft_->base) return stale(s.cur ? s.cur->hash : "nothing");
  if (!s.fresh)
    return refusal(409,
                   "the file on disk changed since the running version was loaded (the file "
                   "watch loads it once it is stable); start a new draft then",
                   {{"reason", "stale"}});
  std::string bytes, diagnostics;
  std::vector<ladder::LineOrigin> origins;
  EditAnswer bad;
  if (!makeBytes(s, draft_->networks, bytes, origins, bad)) return bad;
  std::optional<VerifiedProgram> p = ctl_.verifyEdit(s.path, bytes, diagnostics);
  if (!p) {
    if (log_)
      log_("edit: update by editor '" + editor + "' from " + client +
           " refused: the draft does not verify; the running program is unchanged");
    return refusal(422, "the draft does not verify; the running program is unchanged",
                   {{"diagnostics", mapDiagnostics(diagnostics, s.json ? nullptr : &origins)}});
  }
  // A part the running program has and the draft lacks goes only when the update names it
  // (the page's confirmation lists them); nothing else is ever dropped by an edit.
  std::vector<std::string> lost =
      s.cur->prog ? removedParts(*s.cur->prog, *p) : std::vector<std::string>{};
  std::sort(lost.begin(), lost.end());
  std::sort(removes.begin(), removes.end());
  if (lost != removes) {
    auto list = [](const std::vector<std::string> &v) {
      std::string o;
      for (const std::string &x : v) o += (o.empty() ? "" : ", ") + x;
      return o.empty() ? std::string("none") : o;
    };
    if (log_)
      log_("edit: update by editor '" + editor + "' from " + client +
           " refused: the draft removes " + list(lost) + ", the update names " + list(removes));
    return refusal(409,
                   "the draft removes the part(s) " + list(lost) +
                       " of the running program, "
                       "but the update names " +
                       list(removes) + " in \"removeParts\"; the running program is unchanged",
                   {{"reason", "removes-parts"}, {"removes", lost}});
  }
  const std::string oldHash = s.cur->hash, newHash = formats::sha256Hash(bytes);
  const std::string diff =
      unifiedDiff(s.text, bytes, "a/" + baseName(s.path), "b/" + baseName(s.path));
  // The new file is written (to a temporary file) before the change: a directory that does not
  // take it refuses the update while the old program still runs.
  std::string historyFile, auditError, temp, err;
  if (!prepareProgram(s.path, bytes, temp, err)) {
    if (log_)
      log_("edit: update by editor '" + editor + "' from " + client +
           " refused, the running program is unchanged: " + err);
    return refusal(409,
                   "the program file cannot be written, the running program is unchanged: " + err,
                   {{"reason", "not-writable"}});
  }
  EditedProgram e;
  e.bytes = bytes;
  e.base = draft_->base;
  e.write = [&](std::string &werr) {
    if (!commitProgram(s.path, temp, s.text, historyFile, werr)) return false;
    json rec{{"time", utcNow()}, {"client", client}, {"editor", editor},      {"file", s.path},
             {"old", oldHash},   {"new", newHash},   {"history", historyFile}};
    if (!lost.empty()) rec["removed"] = lost; // parts removed as the update named them
    rec["diff"] =
        diff.size() > kAuditMaxDiff ? diff.substr(0, kAuditMaxDiff) + "\n... (cut)\n" : diff;
    if (!appendAudit(auditPath(s.path), rec, auditError) && log_)
      log_("edit: the audit record could not be written: " + auditError);
    return true;
  };
  const bool ok = ctl_.change(s.path, std::nullopt, err, {}, !lost.empty(), false, &e);
  ::unlink(temp.c_str()); // still there unless it became the program file
  if (e.stale) return stale(exec_.current() ? exec_.current()->hash : "nothing");
  if (!ok && !e.swapped) {
    if (log_)
      log_("edit: update by editor '" + editor + "' from " + client +
           " refused, the running program is unchanged: " + err);
    return refusal(422, "the online change was refused, the running program is unchanged: " + err,
                   {{"diagnostics", mapDiagnostics(err, s.json ? nullptr : &origins)}});
  }
  if (!ok) return refusal(500, err, {{"reason", "not-written"}});
  std::shared_ptr<ProgramVersion> now = exec_.current();
  if (log_)
    log_("edit: update (更新修改) by editor '" + editor + "' from " + client + ": " + oldHash +
         " -> " + newHash + " running as version " + std::to_string(now ? now->id : 0) +
         (lost.empty() ? "" : ", removing " + json(lost).dump() + " as the update named them") +
         ", old file kept as '" + historyFile + "', audit in '" + auditPath(s.path) + "'");
  draft_.reset();
  json r{{"ok", true},          {"version", now ? now->id : 0}, {"old", oldHash},
         {"hash", newHash},     {"history", historyFile},       {"audit", auditPath(s.path)},
         {"init", initJson(*p)}};
  if (!auditError.empty()) r["auditError"] = auditError;
  return {200, std::move(r)};
}

EditAnswer EditSession::discard(const std::string &editor, const std::string &client) {
  std::lock_guard<std::mutex> g(mu_);
  if (!draft_) return refusal(409, "no draft is open", {{"reason", "no-draft"}});
  if (std::optional<EditAnswer> held = heldByOther(editor)) return *held;
  if (log_)
    log_("edit: draft of editor '" + draft_->editor + "' discarded (放弃修改) by " + client +
         "; program, file and state untouched");
  draft_.reset();
  return {200, {{"ok", true}}};
}

std::string unifiedDiff(const std::string &a, const std::string &b, const std::string &nameA,
                        const std::string &nameB) {
  if (a == b) return {};
  const std::vector<std::string> x = splitLines(a), y = splitLines(b);
  // The common head and tail, then a line LCS of the middle (bounded; a larger middle is one
  // replaced block).
  size_t pre = 0;
  while (pre < x.size() && pre < y.size() && x[pre] == y[pre]) ++pre;
  size_t suf = 0;
  while (suf < x.size() - pre && suf < y.size() - pre &&
         x[x.size() - 1 - suf] == y[y.size() - 1 - suf])
    ++suf;
  const size_t n = x.size() - pre - suf, m = y.size() - pre - suf;
  // ops: ' ' same, '-' from x, '+' from y, over the whole files.
  std::vector<std::pair<char, size_t>> ops;
  for (size_t i = 0; i < pre; ++i) ops.push_back({' ', i});
  if (n * m <= 4000000) {
    std::vector<std::vector<uint32_t>> L(n + 1, std::vector<uint32_t>(m + 1, 0));
    for (size_t i = n; i-- > 0;)
      for (size_t j = m; j-- > 0;)
        L[i][j] =
            x[pre + i] == y[pre + j] ? L[i + 1][j + 1] + 1 : std::max(L[i + 1][j], L[i][j + 1]);
    size_t i = 0, j = 0;
    while (i < n || j < m) {
      if (i < n && j < m && x[pre + i] == y[pre + j]) {
        ops.push_back({' ', pre + i});
        ++i;
        ++j;
      } else if (i < n && (j == m || L[i + 1][j] >= L[i][j + 1])) {
        ops.push_back({'-', pre + i++});
      } else {
        ops.push_back({'+', pre + j++});
      }
    }
  } else {
    for (size_t i = 0; i < n; ++i) ops.push_back({'-', pre + i});
    for (size_t j = 0; j < m; ++j) ops.push_back({'+', pre + j});
  }
  for (size_t i = 0; i < suf; ++i) ops.push_back({' ', x.size() - suf + i});
  std::string out = "--- " + nameA + "\n+++ " + nameB + "\n";
  constexpr size_t kContext = 3;
  size_t k = 0;
  while (k < ops.size()) {
    while (k < ops.size() && ops[k].first == ' ') ++k;
    if (k == ops.size()) break;
    const size_t start = k >= kContext ? k - kContext : 0;
    size_t end = k;
    // The hunk grows while the next change is within 2 * context lines.
    for (size_t q = k; q < ops.size(); ++q)
      if (ops[q].first != ' ')
        end = q + 1;
      else if (q - end >= 2 * kContext)
        break;
    const size_t stop = std::min(ops.size(), end + kContext);
    // Line numbers of the hunk in x and y (1-based).
    size_t xl = 0, yl = 0;
    for (size_t q = 0; q < start; ++q) {
      if (ops[q].first != '+') ++xl;
      if (ops[q].first != '-') ++yl;
    }
    size_t xn = 0, yn = 0;
    std::string body;
    for (size_t q = start; q < stop; ++q) {
      const char c = ops[q].first;
      if (c != '+') ++xn;
      if (c != '-') ++yn;
      body += c;
      body += (c == '+' ? y : x)[ops[q].second];
      body += '\n';
    }
    out += "@@ -" + std::to_string(xn ? xl + 1 : xl) + "," + std::to_string(xn) + " +" +
           std::to_string(yn ? yl + 1 : yl) + "," + std::to_string(yn) + " @@\n" + body;
    k = stop;
  }
  return out;
}

} // namespace lj::rt
