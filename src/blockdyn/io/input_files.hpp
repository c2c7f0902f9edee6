// SPDX-License-Identifier: Apache-2.0
#pragma once
// The files a run has read (records, scenarios, assembly files): an output must never overwrite
// one of them. Every reader notes what it opens; every writer (AtomicFile) asks before it
// replaces a file. The same file is recognised through other names (hard or symbolic links) by its
// device and inode. A command starts with an empty list (clear_inputs).
#include <optional>
#include <string>

namespace blockdyn {

void note_input(const std::string& path);
void clear_inputs();
// The input (as it was named when read) that `path` would overwrite, if any.
std::optional<std::string> input_at(const std::string& path);
// Throws std::invalid_argument "<field> = '<path>' is an input of this run (<input>): ..." if
// writing path would overwrite an input.
void require_not_input(const std::string& field, const std::string& path);

// Whether two paths name the same file: the same device and inode when both exist, else the same
// absolute path with symbolic links resolved.
bool same_file(const std::string& a, const std::string& b);

}  // namespace blockdyn
