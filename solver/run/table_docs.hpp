#pragma once
// The documents' tables, rendered from the tables they describe: the scene keys
// (scene/scene_keys.hpp), the fidelity presets (scene/fidelity.hpp), the drag laws
// (coupling/drag_law_table.hpp), the log columns (run/log_columns.hpp), the in-situ
// pipelines (scene/insitu_pipelines.hpp) and the scene fuzzer's dictionary. A document
// holds each between a line with "sphdem docs: NAME" and the next line with
// "end sphdem docs"; `sphdem docs --update FILE...` rewrites them and a unit test
// (tests/unit/docs_test.cpp) fails while a document differs from its tables.
#include <string>
#include <vector>

namespace sphdem {

// The text of the generated block NAME:
//   "keys PREFIX..."    the scene keys of the sections PREFIX... ("" is the top level:
//                       write it as "-"), one markdown table
//   "fidelity presets"  the presets' values of the keys they set
//   "drag laws"         the drag laws with their equations and ranges
//   "log columns"       the columns of log.csv
//   "pipelines"         the in-situ pipelines
//   "fuzz dictionary"   every key name and choice, one libFuzzer dictionary entry a line
// std::invalid_argument for another name.
std::string generated_block(const std::string& name);

// `text` with every generated block rewritten from the tables.
std::string with_generated_blocks(const std::string& text);

// The section prefixes of the scene key table, in its order ("" the top level,
// "species.N.size_distribution" for its law's keys): each generated "keys" block names
// some, and cases/README.md names each once.
std::vector<std::string> scene_key_sections();

}  // namespace sphdem
