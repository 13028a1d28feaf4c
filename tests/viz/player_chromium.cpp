// The HTML player in a real browser: headless Chromium loads the written file (no network), runs
// its script, and the page reports in <div id="status"> whether a JavaScript error happened and
// whether the canvas (and the character alone) is non-blank after a few frames; a screenshot is
// saved to <build>/viz_outputs/player.png. That line is for tests: it stays hidden from people
// unless the page is opened with ?selftest. Skipped, with a message, when Chromium is not
// installed (scripts/test.sh installs Debian's `chromium`). Two browser launches, ~5 s each.
#include <catch2/catch.hpp>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
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

/// One headless Chromium run on a written page: its DOM after the page's script ran, its log, the
/// status line the page wrote after checking itself and the start tag of the element that holds
/// it (both empty when there is none).
struct chromium_run {
  std::string command, page, messages, status, status_tag;
  int rc = -1;
};

/// `query` is appended to the page's file:// address (e.g. "?selftest").
chromium_run run_chromium(const std::string& chromium, const fs::path& html, const fs::path& png,
                          const std::string& query = "") {
  const fs::path dom = fs::path(html).replace_extension(".dom.html");
  const fs::path log = fs::path(html).replace_extension(".chromium.log");
  for (const auto& p : {png, dom, log}) fs::remove(p);
  char tmpl[] = "/tmp/gaitsynth-chromium-XXXXXX";
  const char* profile = mkdtemp(tmpl);
  REQUIRE(profile != nullptr);
  chromium_run r;
  r.command = "timeout 180 '" + chromium +
              "' --headless --no-sandbox --disable-gpu --disable-quic --no-first-run"
              " --disable-background-networking --disable-component-update --disable-sync"
              " --user-data-dir='" +
              std::string(profile) +
              "' --enable-logging=stderr --v=0"
              " --screenshot='" +
              png.string() +
              "' --window-size=1280,800 --virtual-time-budget=3000"
              " --dump-dom 'file://" +
              fs::absolute(html).string() + query + "' > '" + dom.string() + "' 2> '" +
              log.string() + "'";
  r.rc = std::system(r.command.c_str());
  fs::remove_all(profile);
  r.page = read_file(dom);
  r.messages = read_file(log);
  const std::string open = "<div id=\"status\"";
  const auto a = r.page.find(open);
  if (a != std::string::npos) {
    const auto b = r.page.find('>', a), e = r.page.find("</div>", a);
    r.status_tag = r.page.substr(a, b + 1 - a);
    r.status = r.page.substr(b + 1, e - b - 1);
  }
  return r;
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

  const auto m = viz_test::make_biped<floating_root>();
  const auto traj = viz_test::make_walk(m, 3.0, 0.01);
  save_html_player(m, traj, html.string(), {.title = "gaitsynth player (test walk)"});
  const chromium_run r = run_chromium(chromium, html, png);
  INFO("command: " << r.command);
  INFO("chromium log (tail):\n" << tail(r.messages));
  REQUIRE(r.rc == 0);

  // The status the page wrote after checking itself.
  INFO("status: " << r.status);
  CHECK(r.status.rfind("ok ", 0) == 0);
  CHECK(r.status.find("nonblank=1") != std::string::npos);
  CHECK(r.status.find("error") == std::string::npos);
  CHECK(r.messages.find("Uncaught") == std::string::npos);
  // ... which people do not see: the element keeps its `hidden` attribute after the script ran,
  // and the page measured the line as taking no space (shown=0).
  INFO("status element: " << r.status_tag);
  CHECK(r.status_tag.find(" hidden") != std::string::npos);
  CHECK(r.status.find(" shown=0") != std::string::npos);

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

// Also opens the page with ?selftest, which shows the self-check line to people.
TEST_CASE("HTML player with non-finite data (null in its JSON) runs in headless Chromium",
          "[viz][html][chromium]") {
  const std::string chromium = find_chromium();
  if (chromium.empty()) {
    WARN("SKIPPED: chromium not found on PATH; the headless non-finite data test did not run");
    return;
  }
  const fs::path dir = fs::path(GAITSYNTH_BINARY_DIR) / "viz_outputs";
  fs::create_directories(dir);
  const fs::path html = dir / "player_nonfinite.html", png = dir / "player_nonfinite.png";
  const auto m = viz_test::make_biped<planar_root>();
  auto traj = viz_test::make_walk(m, 2.0, 0.01);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  for (std::size_t f = 0; f < traj.frames.size(); f += 7) {
    traj.frames[f].objective_terms[f % 2] = f % 3 ? nan : inf;
    traj.frames[f].contact_force[f % 4].x() = -inf;
  }
  traj.frames.back().objective_terms.clear();  // missing terms are null too
  traj.terrain.nx = traj.terrain.ny = 3;
  traj.terrain.x0 = traj.terrain.y0 = -1;
  traj.terrain.dx = traj.terrain.dy = 1;
  traj.terrain.height = {0, 0, 0, 0, nan, 0, 0, 0, inf};
  save_html_player(m, traj, html.string(), {.autoplay = false});
  const chromium_run r = run_chromium(chromium, html, png, "?selftest");
  INFO("command: " << r.command);
  INFO("chromium log (tail):\n" << tail(r.messages));
  REQUIRE(r.rc == 0);
  INFO("status: " << r.status);
  CHECK(r.status.rfind("ok ", 0) == 0);
  CHECK(r.messages.find("Uncaught") == std::string::npos);
  // Opened with ?selftest, the page shows its self-check line.
  INFO("status element: " << r.status_tag);
  CHECK(r.status_tag.find("hidden") == std::string::npos);
  CHECK(r.status.find(" shown=1") != std::string::npos);
}
