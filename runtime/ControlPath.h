// Where the control socket lives: the private runtime directory serve creates and monitor
// trusts, and the ownership checks monitor applies to a socket it is given (docs/serve.md
// "Control").
#pragma once

#include <string>

namespace lj::rt {

/// The private runtime directory: $LADDERJIT_RUNTIME_DIR if set, else /run/ladderjit for root,
/// else $XDG_RUNTIME_DIR/ladderjit (when that is a 0700 directory of ours), else
/// /tmp/ladderjit-<uid>. With `create` it is made (mkdir 0700, an existing one is accepted
/// only as below); either way it must be a directory (not a symlink) owned by our euid with no
/// group / other permissions. False with `error` naming the path and the problem.
bool controlDir(bool create, std::string &dir, std::string &error);

/// serve's default socket: controlDir(create) + "/serve-<pid>.sock".
bool defaultControlPath(std::string &path, std::string &error);

/// monitor without --control: the one live server socket in controlDir (never a glob of
/// /tmp). False with `error` when there is none or more than one.
bool findControlSocket(std::string &path, std::string &error);

/// "cannot connect to the server at 'PATH': <errno text>", with a hint that fits `err`
/// ("is `ladderjit serve` running?" only for a missing socket or a refused connection).
std::string connectError(const std::string &path, int err);

/// monitor --control PATH: PATH must be a socket owned by our euid or root, in a directory
/// owned by our euid or root that others cannot write to (unless it is sticky, like /tmp).
bool checkControlSocket(const std::string &path, std::string &error);

} // namespace lj::rt
