// The HTML player's script, style and markup (include/gaitsynth/viz/player/*.js, *.css, *.html)
// are the source of truth; player/assets.hpp embeds them. These tests fail when the header is
// stale (someone edited an asset and did not run scripts/embed_player_assets.py), and check the
// JavaScript with `node --check` where Node.js is installed (skipped, with a message, where not).
#include <catch2/catch.hpp>

#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <span>
#include <sstream>
#include <string>
#include <string_view>

#include "gaitsynth/viz/html_player.hpp"
#include "gaitsynth/viz/player/assets.hpp"
#include "viz/viz_fixture.hpp"

using namespace gaitsynth;
namespace fs = std::filesystem;
namespace assets = gaitsynth::viz_detail::player_assets;

namespace {

const fs::path asset_dir = fs::path(GAITSYNTH_SOURCE_DIR) / "include/gaitsynth/viz/player";

std::string read_file(const fs::path& p) {
  std::ifstream f(p, std::ios::binary);
  REQUIRE(f);
  std::ostringstream s;
  s << f.rdbuf();
  return s.str();
}

std::string joined(std::span<const std::string_view> pieces) {
  std::string s;
  for (std::string_view p : pieces) s += p;
  return s;
}

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

/// The first executable `node` or `nodejs` on PATH (Debian's nodejs package installs both); empty
/// when there is none.
std::string find_node() {
  const char* path = std::getenv("PATH");
  if (!path) return {};
  const std::string p(path);
  for (const char* name : {"node", "nodejs"}) {
    for (std::size_t a = 0; a <= p.size();) {
      const std::size_t b = std::min(p.find(':', a), p.size());
      const std::string dir = p.substr(a, b - a);
      const fs::path cand = fs::path(dir) / name;
      std::error_code ec;
      if (!dir.empty() && fs::is_regular_file(cand, ec) &&
          (fs::status(cand, ec).permissions() & fs::perms::owner_exec) != fs::perms::none)
        return cand.string();
      a = b + 1;
    }
  }
  return {};
}

/// Runs `node --check` on a file; returns its exit status, with its messages in `messages`.
int node_check(const std::string& node, const fs::path& file, std::string& messages) {
  const fs::path log = fs::path(GAITSYNTH_BINARY_DIR) / "viz_outputs" / "node_check.log";
  const std::string cmd =
      "'" + node + "' --check '" + file.string() + "' > '" + log.string() + "' 2>&1";
  const int rc = std::system(cmd.c_str());
  messages = read_file(log);
  return rc;
}

}  // namespace

TEST_CASE("player assets: the embedded header equals the .js/.css/.html files",
          "[viz][html][assets]") {
  struct asset {
    const char* file;
    std::span<const std::string_view> pieces;
  };
  for (const asset& a : {asset{"player.css", assets::css}, asset{"player_body.html", assets::body},
                         asset{"player.js", assets::js}}) {
    INFO(a.file << ": if this fails, run scripts/embed_player_assets.py and commit assets.hpp");
    const std::string file = read_file(asset_dir / a.file);
    CHECK(joined(a.pieces) == file);
    // MSVC's limit for one string literal (C2026) is 16380 bytes.
    for (std::string_view p : a.pieces) CHECK(p.size() <= 16000);
  }
}

TEST_CASE("player assets: nothing in them can end their element in the page",
          "[viz][html][assets]") {
  const std::string js = lower(joined(assets::js));
  CHECK(js.find("</script") == std::string::npos);
  CHECK(js.find("<!--") == std::string::npos);
  CHECK(lower(joined(assets::css)).find("</style") == std::string::npos);
  CHECK(lower(joined(assets::body)).find("<script") == std::string::npos);
}

TEST_CASE("player assets: the page's script is valid JavaScript (node --check)",
          "[viz][html][assets][node]") {
  const std::string node = find_node();
  if (node.empty()) {
    WARN(
        "SKIPPED: node not found on PATH (install Debian's 'nodejs' package); player.js was not "
        "syntax-checked");
    return;
  }
  fs::create_directories(fs::path(GAITSYNTH_BINARY_DIR) / "viz_outputs");
  INFO("node: " << node);
  std::string messages;
  {
    const int rc = node_check(node, asset_dir / "player.js", messages);
    INFO("node --check player.js:\n" << messages);
    CHECK(rc == 0);
  }
  // The script exactly as a written page holds it.
  const auto m = viz_test::make_biped<planar_root>();
  std::ostringstream os;
  write_html_player(m, viz_test::make_walk(m, 0.5, 0.01), os);
  const std::string html = os.str();
  const std::string open = "<script>";
  const auto a = html.find(open);
  REQUIRE(a != std::string::npos);
  const auto b = html.find("</script>", a);
  REQUIRE(b != std::string::npos);
  const fs::path extracted = fs::path(GAITSYNTH_BINARY_DIR) / "viz_outputs" / "page_script.js";
  {
    std::ofstream f(extracted, std::ios::binary);
    f << html.substr(a + open.size(), b - a - open.size());
  }
  const int rc = node_check(node, extracted, messages);
  INFO("node --check on the page's script:\n" << messages);
  CHECK(rc == 0);
}

TEST_CASE("player: a long legend stays inside its plot, in columns (node)",
          "[viz][html][assets][node]") {
  const std::string node = find_node();
  if (node.empty()) {
    WARN("SKIPPED: node not found on PATH (install Debian's 'nodejs' package)");
    return;
  }
  fs::create_directories(fs::path(GAITSYNTH_BINARY_DIR) / "viz_outputs");
  const fs::path harness = fs::path(GAITSYNTH_SOURCE_DIR) / "tests" / "viz" / "player_legend.js";
  const fs::path log = fs::path(GAITSYNTH_BINARY_DIR) / "viz_outputs" / "player_legend.log";
  const std::string cmd = "'" + node + "' '" + harness.string() + "' '" +
                          (asset_dir / "player.js").string() + "' > '" + log.string() + "' 2>&1";
  const int rc = std::system(cmd.c_str());
  INFO("node " << harness.filename() << ":\n" << read_file(log));
  CHECK(rc == 0);
}
