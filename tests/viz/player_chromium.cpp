// The HTML player in a real browser: headless Chromium loads the written file (no network), runs
// its script, and the page reports in <div id="status"> whether a JavaScript error happened and
// whether the canvas (and the character alone) is non-blank after a few frames; a screenshot is
// saved to <build>/viz_outputs/player.png. Skipped, with a message, when Chromium is not installed
// (scripts/test.sh installs Debian's `chromium`). One browser launch, ~5 s.
#include <catch2/catch.hpp>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "gaitsynth/viz/html_player.hpp"
#include "viz/viz_fixture.hpp"

using namespace gaitsynth;
namespace fs = std::filesystem;

namespace {

/// GAITSYNTH_CHROMIUM, else the first of the usual names on PATH; empty when none.
std::string find_chromium() {
  if (const char* e = std::getenv("GAITSYNTH_CHROMIUM"); e && *e) return e;
  const char* path = std::getenv("PATH");
  if (!path) return {};
  std::string p(path);
  for (const char* name :
       {"chromium", "chromium-browser", "google-chrome", "google-chrome-stable"}) {
    std::size_t a = 0;
    while (a <= p.size()) {
      const std::size_t b = std::min(p.find(':', a), p.size());
      const fs::path cand = fs::path(p.substr(a, b - a)) / name;
      std::error_code ec;
      if (!p.substr(a, b - a).empty() && fs::is_regular_file(cand, ec) &&
          (fs::status(cand, ec).permissions() & fs::perms::owner_exec) != fs::perms::none)
        return cand.string();
      a = b + 1;
    }
  }
  return {};
}

std::string read_file(const fs::path& p) {
  std::ifstream f(p, std::ios::binary);
  std::ostringstream s;
  s << f.rdbuf();
  return s.str();
}

std::string tail(const std::string& s, std::size_t n = 3000) {
  return s.size() <= n ? s : s.substr(s.size() - n);
}

}  // namespace

TEST_CASE("HTML player runs in headless Chromium without errors and draws",
          "[viz][html][chromium]") {
  const std::string chromium = find_chromium();
  if (chromium.empty()) {
    WARN(
        "SKIPPED: chromium not found on PATH (install Debian's 'chromium' package, or set "
        "GAITSYNTH_CHROMIUM); the headless player test did not run");
    return;
  }
  const fs::path dir = fs::path(GAITSYNTH_BINARY_DIR) / "viz_outputs";
  fs::create_directories(dir);
  const fs::path html = dir / "player.html", png = dir / "player.png";
  const fs::path dom = dir / "player_dom.html", log = dir / "player_chromium.log";
  for (const auto& p : {png, dom, log}) fs::remove(p);

  const auto m = viz_test::make_biped<floating_root>();
  const auto traj = viz_test::make_walk(m, 3.0, 0.01);
  save_html_player(m, traj, html.string(), {.title = "gaitsynth player (test walk)"});

  char tmpl[] = "/tmp/gaitsynth-chromium-XXXXXX";
  const char* profile = mkdtemp(tmpl);
  REQUIRE(profile != nullptr);
  const std::string cmd =
      "timeout 180 '" + chromium +
      "' --headless --no-sandbox --disable-gpu --disable-quic --no-first-run"
      " --disable-background-networking --disable-component-update --disable-sync"
      " --user-data-dir='" +
      std::string(profile) +
      "' --enable-logging=stderr --v=0"
      " --screenshot='" +
      png.string() +
      "' --window-size=1280,800 --virtual-time-budget=3000"
      " --dump-dom 'file://" +
      fs::absolute(html).string() + "' > '" + dom.string() + "' 2> '" + log.string() + "'";
  const int rc = std::system(cmd.c_str());
  fs::remove_all(profile);
  const std::string page = read_file(dom), messages = read_file(log);
  INFO("command: " << cmd);
  INFO("chromium log (tail):\n" << tail(messages));
  REQUIRE(rc == 0);

  // The status the page wrote after checking itself.
  const std::string open = "<div id=\"status\"";
  const auto a = page.find(open);
  REQUIRE(a != std::string::npos);
  const auto b = page.find('>', a), e = page.find("</div>", a);
  const std::string status = page.substr(b + 1, e - b - 1);
  INFO("status: " << status);
  CHECK(status.rfind("ok ", 0) == 0);
  CHECK(status.find("nonblank=1") != std::string::npos);
  CHECK(status.find("error") == std::string::npos);
  CHECK(messages.find("Uncaught") == std::string::npos);

  // A PNG of the requested size.
  const std::string img = read_file(png);
  REQUIRE(img.size() > 1000);
  CHECK(img.compare(0, 8, "\x89PNG\r\n\x1a\n") == 0);
  auto be32 = [&](std::size_t o) {
    return (static_cast<unsigned>(static_cast<unsigned char>(img[o])) << 24) |
           (static_cast<unsigned>(static_cast<unsigned char>(img[o + 1])) << 16) |
           (static_cast<unsigned>(static_cast<unsigned char>(img[o + 2])) << 8) |
           static_cast<unsigned>(static_cast<unsigned char>(img[o + 3]));
  };
  CHECK(be32(16) == 1280u);  // IHDR width
  CHECK(be32(20) == 800u);   // IHDR height
}
