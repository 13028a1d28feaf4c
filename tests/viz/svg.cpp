// SVG outputs: filmstrip, gait-cycle plot and convergence plot are well-formed XML with the
// expected structure; the convergence reader is tolerant of column order and extra columns.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "gaitsynth/viz/convergence_plot_svg.hpp"
#include "gaitsynth/viz/filmstrip_svg.hpp"
#include "gaitsynth/viz/gait_plot_svg.hpp"
#include "viz/viz_fixture.hpp"
#include "viz/xml_check.hpp"

using namespace gaitsynth;

namespace {
std::size_t count(const std::string& s, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t p = s.find(what); p != std::string::npos; p = s.find(what, p + 1)) ++n;
  return n;
}
// Outputs kept in the build tree for a look (docs/viewer.md shows copies).
std::string out_dir() {
  const std::string d = std::string(GAITSYNTH_BINARY_DIR) + "/viz_outputs";
  std::filesystem::create_directories(d);
  return d;
}
}  // namespace

TEST_CASE("the XML checker rejects broken documents", "[viz][svg]") {
  CHECK_NOTHROW(
      viz_test::check_xml("<?xml version=\"1.0\"?>\n<svg a=\"1\"><g><rect/></g></svg>\n"));
  CHECK_THROWS(viz_test::check_xml("<svg><g></svg>"));
  CHECK_THROWS(viz_test::check_xml("<svg a=1/>"));
  CHECK_THROWS(viz_test::check_xml("<svg>&nbsp;</svg>"));
  CHECK_THROWS(viz_test::check_xml("<svg/><svg/>"));
  CHECK_THROWS(viz_test::check_xml("<svg>"));
  CHECK_THROWS(viz_test::check_xml("<svg a=\"1\" a=\"2\"/>"));
  CHECK_THROWS(viz_test::check_xml("<svg><g></G></svg>"));
  CHECK_THROWS(viz_test::check_xml("<svg/>x"));
  CHECK_THROWS(viz_test::check_xml(""));
  // What tinyxml2 accepts and xml_check.hpp refuses.
  CHECK_THROWS(viz_test::check_xml("x<svg/>"));
  CHECK_THROWS(viz_test::check_xml("<svg>&amp</svg>"));
  CHECK_THROWS(viz_test::check_xml("<svg a=\"&#x;\"/>"));
  CHECK_THROWS(viz_test::check_xml("<svg a=\"<\"/>"));
  CHECK_THROWS(viz_test::check_xml("<svg>\x01</svg>"));
  CHECK_THROWS(viz_test::check_xml("<svg><!-- a -- b --></svg>"));
  CHECK_THROWS(viz_test::check_xml("<svg>]]></svg>"));
  CHECK_THROWS(viz_test::check_xml("<!DOCTYPE svg><svg/>"));
  CHECK_THROWS(viz_test::check_xml(" <?xml version=\"1.0\"?><svg/>"));
  // Legal XML passes, with entities decoded.
  const auto ok =
      viz_test::parse_xml("<svg a='&lt;&#65;&#x42;&quot;'><![CDATA[<&>]]>t&amp;<!-- c --></svg>");
  const tinyxml2::XMLElement& svg = *ok->RootElement();
  CHECK(std::string(svg.Attribute("a")) == "<AB\"");
  REQUIRE(svg.FirstChild()->ToText());
  CHECK(svg.FirstChild()->ToText()->CData());
  CHECK(std::string(svg.FirstChild()->Value()) == "<&>");
  CHECK(std::string(svg.FirstChild()->NextSibling()->Value()) == "t&");
}

TEST_CASE("filmstrip SVG: well-formed, one group per strobe frame", "[viz][svg]") {
  const auto m = viz_test::make_biped<planar_root>();
  const auto traj = viz_test::make_walk(m, 3.0, 0.01);
  std::ostringstream os;
  write_filmstrip_svg(m, traj, os, {.interval = 0.25, .title = "test <biped> & walk"});
  const std::string svg = os.str();
  const auto sum = viz_test::check_xml(svg);
  CHECK(sum.root == "svg");
  CHECK(svg.find("xmlns=\"http://www.w3.org/2000/svg\"") != std::string::npos);
  CHECK(count(svg, "class=\"strobe\"") == 13);  // t = 0, 0.25, ..., 3.0
  CHECK(sum.elements.at("polygon") >= 13 * 3);  // pelvis and two feet per strobe, plus terrain
  CHECK(count(svg, "class=\"terrain\"") == 1);
  CHECK(count(svg, "class=\"com-path\"") == 1);
  CHECK(svg.find("test &lt;biped&gt; &amp; walk") != std::string::npos);
  CHECK(count(svg, "class=\"contact\"") >= 13);  // at least one foot on the ground in each
  // Count-based spacing, 3-D model, spread and options.
  const auto m3 = viz_test::make_biped<floating_root>();
  const auto t3 = viz_test::make_walk(m3, 2.0, 0.02);
  std::ostringstream o3;
  save_filmstrip_svg(m3, t3, out_dir() + "/filmstrip.svg", {.count = 6, .spread = 0.35});
  write_filmstrip_svg(m3, t3, o3,
                      {.count = 5, .spread = 0.5, .show_forces = true, .show_times = true});
  CHECK(viz_test::check_xml(o3.str()).root == "svg");
  CHECK(count(o3.str(), "class=\"strobe\"") == 5);
  CHECK(count(o3.str(), "class=\"force\"") >= 5);
  CHECK_THROWS_WITH(write_filmstrip_svg(m, traj, os, {.count = 0}), Catch::Contains("count"));
  CHECK_THROWS_WITH(write_filmstrip_svg(m, traj, os, {.t_begin = 5, .t_end = 6}),
                    Catch::Contains("empty time window"));
}

namespace {
/// Mean x1 of the <line> elements stroked in `colour` (a body side's colour).
double mean_line_x(const std::string& svg, const std::string& colour) {
  double sum = 0;
  int n = 0;
  for (std::size_t at = svg.find("<line x1=\""); at != std::string::npos;
       at = svg.find("<line x1=\"", at + 1)) {
    const std::size_t end = svg.find("/>", at);
    if (svg.substr(at, end - at).find("stroke=\"" + colour + "\"") == std::string::npos) continue;
    sum += std::stod(svg.substr(at + 10));
    ++n;
  }
  return n > 0 ? sum / n : std::nan("");
}
}  // namespace

TEST_CASE("filmstrip SVG, front view: frames side by side, the left leg on the viewer's right",
          "[viz][svg]") {
  const auto m = viz_test::make_biped<floating_root>();
  const auto traj = viz_test::make_walk(m, 2.0, 0.02);
  std::ostringstream one, three;
  write_filmstrip_svg(m, traj, one, {.count = 1, .view = filmstrip_view::front});
  // Seen from +x, the walker's left (+y, blue) is to the right of its right leg (orange).
  CHECK(mean_line_x(one.str(), "#6f9bd8") > mean_line_x(one.str(), "#dd8452") + 50);
  write_filmstrip_svg(m, traj, three, {.count = 3, .spread = 1.0, .view = filmstrip_view::front});
  CHECK(viz_test::check_xml(three.str()).root == "svg");
  CHECK(count(three.str(), "class=\"strobe\"") == 3);
  CHECK(count(three.str(), "class=\"terrain\"") == 3);  // a ground strip under each frame
  CHECK(count(three.str(), "class=\"com-path\"") == 0);
  // Three frames 1 m apart make a picture wider than tall; one frame, taller than wide.
  const auto aspect = [](const std::string& svg) {
    const double w = std::stod(svg.substr(svg.find("width=\"") + 7));
    const double h = std::stod(svg.substr(svg.find("height=\"") + 8));
    return w / h;
  };
  CHECK(aspect(one.str()) < 1.0);
  CHECK(aspect(three.str()) > 1.0);
}

TEST_CASE("gait plot SVG: a reference curve over one panel, in its band and named", "[viz][svg]") {
  const auto m = viz_test::make_biped<planar_root>();
  const auto traj = viz_test::make_walk(m, 4.0, 0.01);
  gait_plot_options o;
  // Far above the walk's knee curve, so that the panel's range must grow to hold it.
  o.references = {{.channel = 1,
                   .label = "human <ref>",
                   .percent = {0, 50, 100},
                   .mean = {500, 600, 500},
                   .sd = {10, 10, 10}}};
  std::ostringstream os;
  write_gait_plot_svg(m, traj, os, o);
  const std::string svg = os.str();
  CHECK(viz_test::check_xml(svg).root == "svg");
  CHECK(count(svg, "class=\"reference\"") == 1);
  CHECK(count(svg, "class=\"reference-band\"") == 1);
  CHECK(svg.find("dashed green: human &lt;ref&gt; (") != std::string::npos);
  // The y axis of panel 1 reaches the reference's top (610) and the others do not.
  const std::size_t p1 = svg.find("id=\"panel-1\""), p2 = svg.find("id=\"panel-2\"");
  CHECK(svg.substr(p1, p2 - p1).find(">600<") != std::string::npos);
  CHECK(svg.substr(p2).find(">600<") == std::string::npos);
  // Without s.d.: the line alone.
  o.references[0].sd.clear();
  std::ostringstream o2;
  write_gait_plot_svg(m, traj, o2, o);
  CHECK(count(o2.str(), "class=\"reference-band\"") == 0);
  CHECK(count(o2.str(), "class=\"reference\"") == 1);
  // Bad references are named.
  o.references[0].channel = 3;
  CHECK_THROWS_WITH(write_gait_plot_svg(m, traj, o2, o),
                    Catch::Contains("human <ref>") && Catch::Contains("panel 3 of 3"));
  o.references[0].channel = 0;
  o.references[0].mean = {1, 2};
  CHECK_THROWS_WITH(write_gait_plot_svg(m, traj, o2, o), Catch::Contains("equal sizes"));
  o.references[0].mean = {1, std::nan(""), 3};
  CHECK_THROWS_WITH(write_gait_plot_svg(m, traj, o2, o), Catch::Contains("not finite"));
}

TEST_CASE("gait plot SVG: three panels with mean, band and cycles", "[viz][svg]") {
  const auto m = viz_test::make_biped<planar_root>();
  const auto traj = viz_test::make_walk(m, 4.0, 0.01);
  std::ostringstream os;
  write_gait_plot_svg(m, traj, os);
  const std::string svg = os.str();
  const auto sum = viz_test::check_xml(svg);
  CHECK(sum.root == "svg");
  CHECK(count(svg, "class=\"panel\"") == 3);
  CHECK(count(svg, "class=\"band\"") == 3);
  CHECK(count(svg, "class=\"mean\"") == 3);
  const auto d = gait_cycles(m, traj);
  CHECK(count(svg, "class=\"cycle\"") == 3u * d.num_cycles());
  CHECK(svg.find("between heel strikes of lfoot") != std::string::npos);
  save_gait_plot_svg(m, traj, out_dir() + "/gait.svg");
  // No strikes: still a valid figure, saying so.
  auto still = viz_test::make_walk(m, 0.4, 0.01);
  for (auto& f : still.frames) std::fill(f.contact_active.begin(), f.contact_active.end(), 0);
  std::ostringstream o2;
  write_gait_plot_svg(m, still, o2);
  CHECK(viz_test::check_xml(o2.str()).root == "svg");
  CHECK(o2.str().find("no complete gait cycle") != std::string::npos);
}

TEST_CASE("convergence log: columns found by name in any order", "[viz][svg]") {
  const std::string csv =
      "# optimizer log\n"
      "Sigma, Median [J], restart, note, Evaluations, best (J), generation\n"
      "0.5, 100, 0, start, 16, 90, 1\n"
      "0.4, 60, 0, -, 32, 50, 2\n"
      "\n"
      "0.3, 20, 0, -, 48, 10, 3\n"
      "0.6, 80, 1, restart, 64, 10, 4\n"
      "0.1, 2, 1, -, 80, 0.5, 5\n";
  std::istringstream is(csv);
  const convergence_log log = read_convergence_csv(is, "log.csv");
  REQUIRE(log.rows.size() == 5);
  CHECK(log.find({"best"}) == 5);
  CHECK(log.find({"median"}) == 1);
  CHECK(log.find("EVALUATIONS") == 4);
  CHECK(std::isnan(log.rows[0][3]));  // text cell
  std::ostringstream os;
  write_convergence_plot_svg(log, os);
  const std::string svg = os.str();
  CHECK(viz_test::check_xml(svg).root == "svg");
  CHECK(count(svg, "class=\"series\"") == 3);   // best, median, sigma
  CHECK(count(svg, "class=\"restart\"") == 2);  // in both panels
  CHECK(svg.find("data-column=\"best (J)\"") != std::string::npos);
  // Explicit columns, and a missing one named in the error.
  std::ostringstream o2;
  write_convergence_plot_svg(
      log, o2, {.x_column = "generation", .y_columns = {"best"}, .sigma_column = "-"});
  CHECK(count(o2.str(), "class=\"series\"") == 1);
  CHECK_THROWS_WITH(write_convergence_plot_svg(log, o2, {.y_columns = {"fitness"}}),
                    Catch::Contains("no column 'fitness'") && Catch::Contains("'Sigma'"));
  // A short row names its line.
  std::istringstream bad("generation,best\n1,2\n3\n");
  CHECK_THROWS_WITH(read_convergence_csv(bad, "bad.csv"),
                    Catch::Contains("bad.csv") && Catch::Contains("line 3"));
  std::istringstream empty("# nothing\n");
  CHECK_THROWS_WITH(read_convergence_csv(empty), Catch::Contains("no header"));
  // The log of optimizers/minimize.hpp: quoted parameter names, stage and restart markers.
  std::istringstream b(
      "stage,restart,iteration,evaluations,best,iteration_best,iteration_median,iteration_worst,"
      "step_size,axis_ratio,batch_size,non_finite,elapsed_s,\"kp, hip\",\"say \"\"hi\"\"\"\n"
      "0,0,1,10,5,5,6,7,0.3,1,10,0,0.1,1.5,2\n"
      "0,1,2,20,4,4,5,6,0.2,1,10,0,0.2,1.4,2.1\n"
      "1,0,3,30,3,3,4,5,0.1,1,10,0,0.3,1.3,2.2\n");
  const convergence_log blog = read_convergence_csv(b);
  REQUIRE(blog.columns.size() == 15);
  CHECK(blog.columns[13] == "kp, hip");
  CHECK(blog.columns[14] == "say \"hi\"");
  CHECK(blog.rows[2][13] == 1.3);
  std::ostringstream o3;
  write_convergence_plot_svg(blog, o3);
  CHECK(viz_test::check_xml(o3.str()).root == "svg");
  CHECK(count(o3.str(), "class=\"series\"") == 4);   // best, iteration_median, _worst, step_size
  CHECK(count(o3.str(), "class=\"restart\"") == 4);  // rows 2 and 3, in both panels
  // File round trip.
  const std::string path = out_dir() + "/convergence.csv";
  {
    std::ofstream f(path);
    f << csv;
  }
  save_convergence_plot_svg(path, out_dir() + "/convergence.svg");
  CHECK(std::filesystem::file_size(out_dir() + "/convergence.svg") > 500);
}

TEST_CASE("nice_ticks ends on ranges below the values' resolution (found by fuzzing)",
          "[viz][svg][bad_input]") {
  // A range of 2 at 1.3e16: the step is below one ulp of the values, so stepping never advanced.
  const auto t = gaitsynth::viz_detail::nice_ticks(13115550548573230.0, 13115550548573232.0);
  CHECK(t.size() <= 1000);
  const auto u = gaitsynth::viz_detail::nice_ticks(0.0, 10.0);
  REQUIRE(u.size() == 6);
  CHECK(u.front() == 0.0);
  CHECK(u.back() == 10.0);
}

TEST_CASE("tick_decimals of equal ticks (found by fuzzing)", "[viz][svg][bad_input]") {
  // Ticks below the values' resolution come out equal: -log10(0) = inf, whose conversion to int
  // was undefined (UBSan: "inf is outside the range of representable values of type 'int'").
  CHECK(gaitsynth::viz_detail::tick_decimals({1e33, 1e33}) == 6);
  CHECK(gaitsynth::viz_detail::tick_decimals({0.0, 0.5}) == 1);
  CHECK(gaitsynth::viz_detail::tick_decimals({0.0, 1e-9}) == 6);
  CHECK(gaitsynth::viz_detail::tick_decimals({0.0, 100.0}) == 0);
}
