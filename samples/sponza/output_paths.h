#pragma once
// Output files are checked before anything is rendered (a render can take minutes on a software
// device): the folder is created if missing and the file must be writable. Nothing is left behind by
// the check itself.
#include <string>

#include "caustics/rhi/result.h"

namespace caustics::sample {

// `option` names the command-line option in the error ("--out: cannot write '/x/y.png': ...").
Status checkWritable(const std::string& option, const std::string& path);

// Writes `text` to `path`, failing (naming the path) if the file could not be written completely.
Status writeTextFile(const std::string& option, const std::string& path, const std::string& text);

}  // namespace caustics::sample
