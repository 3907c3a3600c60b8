// The file-system questions the loader asks about template directories, answered with POSIX
// calls on plain strings: std::filesystem paths split and copied their components on every
// question (a cold compile spent ~0.15 M instructions there), and a directory is listed with
// getdents64 into a buffer on the stack (opendir allocated 32 KiB per listing). Rules:
// answers match what std::filesystem gave (symbolic links followed, `.` and `..` never
// listed); no caching, a directory is read afresh on every question.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace smachac::tmpl {

/// `dir/name` as std::filesystem::path(dir) / name spells it for a relative `name`: no
/// separator added after an empty `dir` or one ending in `/`.
std::string joinTemplatePath(std::string_view dir, std::string_view name);

/// `path` as std::filesystem::path::lexically_normal spells it (returned as it is when it
/// has no `.`, `..` or empty component to remove).
std::string lexicallyNormal(std::string path);

/// Whether `path` names a regular file (through symbolic links).
bool isRegularTemplateFile(const std::string& path);

/// The names of the regular files in directory `dir`, in the order the directory lists them;
/// empty when it cannot be read.
std::vector<std::string> regularFilesIn(const std::string& dir);

}  // namespace smachac::tmpl
