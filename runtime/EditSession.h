// The ladder editor's server side (docs/ladder-edit.md): THE draft of the running program (the
// network JSON an editor page sends, one holder at a time), its check (the verifier's diagnostics
// mapped to part, rung and element), 更新修改 (the draft goes live through the controller's
// online change, then the served PROGRAM is written atomically with a numbered history copy of
// the old file and an audit record) and 放弃修改 (the draft is dropped, nothing else changes).
// The live view's /api/edit routes call it (runtime/LiveView.h); it never touches the scan thread.
#pragma once

#include "runtime/Controller.h"
#include "runtime/Executive.h"

#include <nlohmann/json.hpp>

#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

namespace lj::rt {

/// An answer of an edit route: the HTTP status and its JSON body.
struct EditAnswer {
  unsigned status = 200;
  nlohmann::json body;
};

class EditSession {
public:
  using Log = std::function<void(const std::string &)>;
  EditSession(Executive &exec, Controller &ctl, Log log);

  /// GET /api/edit: the running version (hash, network JSON, whether it can be edited), the open
  /// draft (holder, since, base) and what an update does with the init part.
  EditAnswer status();
  /// POST /api/edit/ACTION (`action`: draft, check, update, discard) with `body` from the client
  /// at `client` ("ADDR:PORT").
  EditAnswer post(const std::string &action, const nlohmann::json &body, const std::string &client);

  /// The audit log and the history folder of PROGRAM `path` (docs/ladder-edit.md "Files").
  static std::string auditPath(const std::string &path);
  static std::string historyDir(const std::string &path);

  struct Draft {
    std::string editor, client, since, base;
    nlohmann::json networks; ///< the network JSON as sent (without base, editor, takeOver)
  };

private:
  EditAnswer draft(const nlohmann::json &body, const std::string &editor,
                   const std::string &client);
  EditAnswer check(const std::string &editor);
  /// `removes`: the parts the operator agreed to remove (removeParts; the draft's lost parts
  /// must be exactly these).
  EditAnswer update(const std::string &editor, const std::string &client,
                    std::vector<std::string> removes);
  EditAnswer discard(const std::string &editor, const std::string &client);
  /// A draft open by another editor: the 409 naming it, else nullopt. Call with mu_ held.
  std::optional<EditAnswer> heldByOther(const std::string &editor) const;
  /// No draft, or one open by another editor: the 409, else nullopt. Call with mu_ held.
  std::optional<EditAnswer> notHeldBy(const std::string &editor) const;

  Executive &exec_;
  Controller &ctl_;
  Log log_;
  std::mutex mu_; // the draft; one check / update at a time
  std::optional<Draft> draft_;
};

/// A unified diff of `a` and `b` (`---`/`+++` named `nameA`/`nameB`, 3 lines of context), empty
/// when they are equal.
std::string unifiedDiff(const std::string &a, const std::string &b, const std::string &nameA,
                        const std::string &nameB);

} // namespace lj::rt
