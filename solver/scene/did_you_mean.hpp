#pragma once
// "Did you mean ...?" for a misspelt scene key, section or choice: the allowed name
// closest to what the file gave by the optimal-string-alignment edit distance (inserts,
// deletes, substitutions and swaps of two neighbours; case ignored), when it is close:
// at most 1 edit where either name has at most 4 characters, at most 2 otherwise, and
// fewer edits than the shorter name has characters (so 'x' suggests nothing).
#include <cstddef>
#include <string>
#include <vector>

namespace sphdem {

// Edits from a to b, case ignored.
std::size_t edit_distance(const std::string& a, const std::string& b);

// The closest of `names` to `got` under the rule above (the first on a tie), or "".
std::string closest_name(const std::string& got, const std::vector<std::string>& names);

// "; did you mean 'NAME'?" for the closest name, or "" when none is close.
std::string did_you_mean(const std::string& got, const std::vector<std::string>& names);

}  // namespace sphdem
