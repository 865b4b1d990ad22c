// The documents hold the tables they describe as rendered from them (run/table_docs.hpp):
// cases/README.md (scene keys, presets, drag laws, log columns), pipelines/README.md
// (the pipelines) and the scene fuzzer's dictionary. A document that differs fails here
// at its first differing line; `build/app/sphdem docs --update FILE` rewrites it. Also:
// each section of the key table has its one table in cases/README.md, and the in-situ
// pipelines of the table are the Catalyst scripts of pipelines/.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>

#include "run/table_docs.hpp"
#include "scene/insitu_pipelines.hpp"

using namespace sphdem;
namespace fs = std::filesystem;

namespace {

const fs::path kSource = SPHDEM_SOURCE_DIR;

std::string read_text(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

TEST(Docs, EveryGeneratedTableIsTheTablesOwn) {
  for (const char* file : {"cases/README.md", "pipelines/README.md", "tests/fuzz/scene.dict"}) {
    SCOPED_TRACE(file);
    const std::string text = read_text(kSource / file);
    ASSERT_FALSE(text.empty());
    ASSERT_NE(text.find("sphdem docs:"), std::string::npos) << "no generated block";
    const std::string now = with_generated_blocks(text);
    if (now == text) continue;
    std::stringstream a(text), b(now);
    std::string la, lb;
    for (int line = 1; std::getline(a, la) && std::getline(b, lb); ++line)
      if (la != lb) {
        ADD_FAILURE() << file << ":" << line << " differs from the tables:\n  has:  " << la
                      << "\n  want: " << lb << "\nrun: build/app/sphdem docs --update " << file;
        break;
      }
  }
}

TEST(Docs, EachSectionOfTheKeyTableHasItsOneTable) {
  const std::string text = read_text(kSource / "cases/README.md");
  std::map<std::string, int> shown;
  std::stringstream in(text);
  for (std::string line; std::getline(in, line);) {
    const auto at = line.find("sphdem docs: keys ");
    if (at == std::string::npos) continue;
    std::stringstream names(line.substr(at + 18));
    for (std::string s; names >> s && s != "-->";) ++shown[s == "-" ? "" : s];
  }
  for (const std::string& s : scene_key_sections())
    EXPECT_EQ(shown[s], 1) << "section '" << s << "' in " << shown[s]
                           << " tables of cases/README.md (a 'keys' block must name it once)";
}

TEST(Docs, ThePipelinesAreTheCatalystScriptsOfPipelines) {
  std::set<std::string> table, scripts;
  for (const InSituPipeline& p : kInSituPipelines) table.insert(p.name);
  for (const auto& entry : fs::directory_iterator(kSource / "pipelines"))
    if (entry.path().extension() == ".py" &&
        read_text(entry.path()).find("def catalyst_execute(") != std::string::npos)
      scripts.insert(entry.path().stem().string());
  EXPECT_EQ(table, scripts) << "solver/scene/insitu_pipelines.hpp against pipelines/*.py";
}
