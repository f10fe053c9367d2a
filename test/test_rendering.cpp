// Tests of the headless software renderer (SpectralSeg/Rendering).

#include <SpectralSeg/Rendering/Color_map.h>
#include <SpectralSeg/Rendering/Image.h>
#include <SpectralSeg/Rendering/Software_rasterizer.h>
#include <SpectralSeg/Rendering/render_png.h>
#include <SpectralSeg/Rendering/write_png.h>

#include <catch2/catch.hpp>

#include <array>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using namespace SpectralSeg::Rendering;
using Points = std::vector<std::array<double, 3>>;
using Triangles = std::vector<std::array<std::size_t, 3>>;

const Rgb white{255, 255, 255};
const Rgb red{255, 0, 0};
const Rgb blue{0, 0, 255};
const std::array<double, 3> front_direction{0.0, 0.0, -1.0};
const std::array<double, 3> back_direction{0.0, 0.0, 1.0};
const std::array<double, 3> y_up{0.0, 1.0, 0.0};

bool is_white(const Rgb& c) { return c == white; }

bool red_dominant(const Rgb& c) { return c.r > 100 && c.b < 50 && c.g < 50; }

bool blue_dominant(const Rgb& c) { return c.b > 100 && c.r < 50 && c.g < 50; }

std::filesystem::path unique_temp_path(const std::string& stem)
{
  const auto tick = std::chrono::steady_clock::now().time_since_epoch().count();
  return std::filesystem::temp_directory_path()
         / ("spectralseg_" + stem + "_" + std::to_string(tick) + ".png");
}

std::vector<unsigned char> read_bytes(const std::filesystem::path& path)
{
  std::ifstream in(path, std::ios::binary);
  return std::vector<unsigned char>(std::istreambuf_iterator<char>(in),
                                    std::istreambuf_iterator<char>());
}

std::uint32_t big_endian_u32(const std::vector<unsigned char>& bytes, std::size_t at)
{
  return (std::uint32_t(bytes[at]) << 24) | (std::uint32_t(bytes[at + 1]) << 16)
         | (std::uint32_t(bytes[at + 2]) << 8) | std::uint32_t(bytes[at + 3]);
}

// Red triangle at z = 0.5 in front of a blue square at z = 0, both around the
// origin; `red_first` controls the submission order.
void red_over_blue(bool red_first, Points& points, Triangles& triangles, std::vector<Rgb>& colors)
{
  points = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0},
            {-0.5, -0.5, 0.5}, {0.5, -0.5, 0.5}, {0.0, 0.5, 0.5}};
  const Triangles square{{0, 1, 2}, {0, 2, 3}};
  const std::array<std::size_t, 3> small{4, 5, 6};
  triangles.clear();
  colors.clear();
  if(red_first)
  {
    triangles.push_back(small);
    colors.push_back(red);
  }
  for(const auto& t : square)
  {
    triangles.push_back(t);
    colors.push_back(blue);
  }
  if(!red_first)
  {
    triangles.push_back(small);
    colors.push_back(red);
  }
}

} // namespace

TEST_CASE("field_color runs from blue to red through HSL hue", "[rendering][color]")
{
  const Rgb low = field_color(0.0);
  const Rgb high = field_color(1.0);
  const Rgb mid = field_color(0.5);
  CHECK(low.b > 200);
  CHECK(low.r < 50);
  CHECK(low.g < 50);
  CHECK(high.r > 200);
  CHECK(high.g < 50);
  CHECK(high.b < 50);
  CHECK(mid.g > 200); // hue 120: green
  CHECK(mid.r < 50);
  CHECK(mid.b < 50);
  CHECK(field_color(-3.0) == low);
  CHECK(field_color(7.0) == high);
  CHECK(field_color(std::nan("")) == low);
}

TEST_CASE("label colours are distinct, deterministic and cyclic", "[rendering][color]")
{
  for(std::size_t i = 0; i < 10; ++i)
    for(std::size_t j = i + 1; j < 10; ++j)
    {
      INFO("labels " << i << " and " << j);
      CHECK(label_color(i) != label_color(j));
    }
  for(std::size_t i = 0; i < 20; ++i)
  {
    CHECK(label_color(i) != missing_color());
    CHECK(label_color(i) != white);
  }
  CHECK(label_color(3) == label_color(3));
  CHECK(label_color(20) == label_color(0));
  CHECK(label_color(47) == label_color(7));
}

TEST_CASE("field_colors normalises finite values and greys out the others", "[rendering][color]")
{
  const double inf = std::numeric_limits<double>::infinity();
  const std::vector<Rgb> c = field_colors({10.0, 30.0, inf, std::nan(""), 20.0, -inf});
  REQUIRE(c.size() == 6);
  CHECK(c[0] == field_color(0.0));
  CHECK(c[1] == field_color(1.0));
  CHECK(c[2] == missing_color());
  CHECK(c[3] == missing_color());
  CHECK(c[4] == field_color(0.5));
  CHECK(c[5] == missing_color());

  for(const Rgb& k : field_colors({4.0, 4.0, 4.0}))
    CHECK(k == field_color(0.0));
  CHECK(field_colors({}).empty());

  const std::vector<Rgb> l = label_colors({0, -1, 2, -7});
  REQUIRE(l.size() == 4);
  CHECK(l[0] == label_color(0));
  CHECK(l[1] == missing_color());
  CHECK(l[2] == label_color(2));
  CHECK(l[3] == missing_color());
}

TEST_CASE("Image pixel access, fill and clipped paste", "[rendering][image]")
{
  Image dst(4, 3);
  REQUIRE(dst.rgb.size() == 36);
  CHECK(dst.pixel(3, 2) == white);
  dst.set_pixel(1, 2, red);
  CHECK(dst.pixel(1, 2) == red);
  CHECK(dst.pixel(2, 1) == white);

  Image src(2, 2, blue);
  dst.paste(src, 3, -1); // only src(0,1) lands at dst(3,0)
  CHECK(dst.pixel(3, 0) == blue);
  CHECK(dst.pixel(2, 0) == white);
  CHECK(dst.pixel(3, 1) == white);
  dst.paste(src, 10, 10); // fully outside: no effect
  dst.fill(red);
  CHECK(dst.pixel(0, 0) == red);
  CHECK(dst.pixel(3, 2) == red);
}

TEST_CASE("a large triangle facing the camera covers the centre only", "[rendering][raster]")
{
  const Points points{{-1, -1, 0}, {1, -1, 0}, {0, 1, 0}};
  const Triangles triangles{{0, 1, 2}};
  for(bool supersample : {true, false})
  {
    const Software_rasterizer rasterizer(64, 48, supersample);
    const Image img = rasterizer.render(points, triangles, {red}, front_direction, y_up);
    REQUIRE(img.width == 64);
    REQUIRE(img.height == 48);
    CHECK(red_dominant(img.pixel(32, 24)));
    CHECK(is_white(img.pixel(0, 0)));
    CHECK(is_white(img.pixel(63, 0)));
  }
}

TEST_CASE("front view is upright with +X to the right", "[rendering][raster]")
{
  // Red triangle at the top right, blue triangle at the bottom left.
  const Points points{{0.5, 0.5, 0}, {1, 0.5, 0}, {1, 1, 0},
                      {-1, -1, 0}, {-0.5, -1, 0}, {-1, -0.5, 0}};
  const Triangles triangles{{0, 1, 2}, {3, 4, 5}};
  const Software_rasterizer rasterizer(100, 100, false);
  const Image img = rasterizer.render(points, triangles, {red, blue}, front_direction, y_up);
  // Fitted scale: 0.5 * 100 * 0.95 / sqrt(2) pixels per unit around the origin.
  CHECK(red_dominant(img.pixel(77, 27)));  // centroid (0.83, 0.67)
  CHECK(blue_dominant(img.pixel(22, 77))); // centroid (-0.83, -0.83)
  CHECK(is_white(img.pixel(15, 15)));
  CHECK(is_white(img.pixel(85, 85)));
}

TEST_CASE("the z-buffer keeps the nearest face", "[rendering][raster]")
{
  Points points;
  Triangles triangles;
  std::vector<Rgb> colors;
  const Software_rasterizer rasterizer(64, 64);
  for(bool red_first : {true, false})
  {
    INFO("red submitted first: " << red_first);
    red_over_blue(red_first, points, triangles, colors);
    const Image front = rasterizer.render(points, triangles, colors, front_direction, y_up);
    CHECK(red_dominant(front.pixel(32, 32)));  // overlap: red is nearer
    CHECK(blue_dominant(front.pixel(13, 32))); // blue only, near the left edge
    const Image back = rasterizer.render(points, triangles, colors, back_direction, y_up);
    CHECK(blue_dominant(back.pixel(32, 32))); // from behind, blue is nearer
  }
}

TEST_CASE("faces sharing edges leave no gaps", "[rendering][raster]")
{
  // A disk made of a fan of 97 thin triangles, not supersampled.
  const std::size_t n = 97;
  Points points{{0, 0, 0}};
  Triangles triangles;
  const double pi = std::acos(-1.0);
  for(std::size_t i = 0; i < n; ++i)
    points.push_back({std::cos(2 * pi * i / n), std::sin(2 * pi * i / n), 0.0});
  for(std::size_t i = 0; i < n; ++i)
    triangles.push_back({0, 1 + i, 1 + (i + 1) % n});
  const std::vector<Rgb> colors(n, Rgb{200, 200, 0});
  const int size = 101;
  const Software_rasterizer rasterizer(size, size, false);
  const Image img = rasterizer.render(points, triangles, colors, front_direction, y_up);
  const double radius_px = 0.5 * size * 0.95; // fitted radius: margin of 5%
  std::size_t holes = 0, covered = 0;
  for(int y = 0; y < size; ++y)
    for(int x = 0; x < size; ++x)
    {
      const double dx = x + 0.5 - 0.5 * size, dy = y + 0.5 - 0.5 * size;
      const double d = std::sqrt(dx * dx + dy * dy);
      if(d < 0.95 * radius_px && is_white(img.pixel(x, y)))
        ++holes;
      if(d > radius_px + 1.0 && !is_white(img.pixel(x, y)))
        ++covered;
    }
  CHECK(holes == 0);
  CHECK(covered == 0);
}

TEST_CASE("shading is two-sided and depends on the face orientation", "[rendering][raster]")
{
  const Points points{{-1, -1, 0}, {1, -1, 0}, {0, 1, 0}};
  const Software_rasterizer rasterizer(32, 32);
  const Image a = rasterizer.render(points, {{0, 1, 2}}, {red}, front_direction, y_up);
  const Image b = rasterizer.render(points, {{0, 2, 1}}, {red}, front_direction, y_up);
  CHECK(a.rgb == b.rgb);

  const Points tilted{{-1, -1, -1}, {1, -1, -1}, {0, 1, 1}};
  const Image c = rasterizer.render(tilted, {{0, 1, 2}}, {red}, front_direction, y_up);
  CHECK(red_dominant(c.pixel(16, 16)));
  CHECK(c.pixel(16, 16).r != a.pixel(16, 16).r);
}

TEST_CASE("degenerate and non-finite triangles are skipped", "[rendering][raster]")
{
  const double nan = std::nan("");
  const double inf = std::numeric_limits<double>::infinity();
  const Points points{{-1, -1, 0}, {1, -1, 0}, {0, 1, 0}, {nan, 0, 0}, {0, inf, 0}, {0, 0, 0}};
  const Software_rasterizer rasterizer(32, 32);
  const Triangles bad{{0, 0, 1}, {0, 3, 1}, {4, 1, 2}, {5, 5, 5}, {0, 1, 0}};
  const Image only_bad = rasterizer.render(points, bad, std::vector<Rgb>(bad.size(), red),
                                           front_direction, y_up);
  for(unsigned char v : only_bad.rgb)
    CHECK(v == 255);

  Triangles mixed = bad;
  mixed.push_back({0, 1, 2});
  const Image img = rasterizer.render(points, mixed, std::vector<Rgb>(mixed.size(), red),
                                      front_direction, y_up);
  CHECK(red_dominant(img.pixel(16, 16)));
}

TEST_CASE("an empty mesh gives a white image of the requested size", "[rendering][raster]")
{
  const Image single = Software_rasterizer(20, 10).render({}, {}, {}, front_direction, y_up);
  CHECK(single.width == 20);
  CHECK(single.height == 10);
  Render_options options;
  options.view_width = 16;
  options.view_height = 12;
  const Image img = render_face_colors({}, {}, {}, options);
  CHECK(img.width == 3 * 16);
  CHECK(img.height == 12);
  REQUIRE(img.rgb.size() == 3u * 48u * 12u);
  for(unsigned char v : img.rgb)
    CHECK(v == 255);
  // Points without triangles are not drawn either.
  const Image lonely = render_face_colors({{0, 0, 0}, {1, 2, 3}}, {}, {}, options);
  CHECK(lonely.rgb == img.rgb);
}

TEST_CASE("render_face_colors composes the default views side by side", "[rendering][views]")
{
  const std::vector<View> views = default_views();
  REQUIRE(views.size() == 3);
  CHECK(views[0].name == "front");
  CHECK(views[1].name == "side");
  CHECK(views[2].name == "back");

  // A tetrahedron-like closed shape is visible in every view.
  const Points points{{0, 1, 0}, {-1, -1, 1}, {1, -1, 1}, {0, -1, -1}};
  const Triangles triangles{{0, 1, 2}, {0, 2, 3}, {0, 3, 1}, {1, 3, 2}};
  Render_options options;
  options.view_width = 40;
  options.view_height = 30;
  const Image img = render_face_colors(points, triangles, label_colors({0, 1, 2, 3}), options);
  REQUIRE(img.width == 120);
  REQUIRE(img.height == 30);
  for(int v = 0; v < 3; ++v)
  {
    INFO("view " << v);
    CHECK_FALSE(is_white(img.pixel(40 * v + 20, 15)));
    CHECK(is_white(img.pixel(40 * v + 1, 1)));
  }
}

// The share of non-white pixels of a picture.
double coverage(const Image& img)
{
  std::size_t drawn = 0;
  for(int y = 0; y < img.height; ++y)
    for(int x = 0; x < img.width; ++x)
      drawn += is_white(img.pixel(x, y)) ? 0 : 1;
  return double(drawn) / double(img.width) * 1. / double(img.height);
}

// A closed box [0,sx] x [0,sy] x [0,sz] of 12 triangles, outward oriented.
void add_box(Points& points, Triangles& triangles, double sx, double sy, double sz, double x0 = 0.)
{
  const std::size_t o = points.size();
  for(int i = 0; i < 8; ++i)
    points.push_back({x0 + (i & 1 ? sx : 0.), i & 2 ? sy : 0., i & 4 ? sz : 0.});
  const std::array<std::array<std::size_t, 3>, 12> box{{{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                                                        {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}}};
  for(const auto& t : box)
    triangles.push_back({o + t[0], o + t[1], o + t[2]});
}

TEST_CASE("the default views come from the shape: a flat table is seen from above, not edge-on", "[rendering][views]")
{
  // a table top 4 x 0.1 x 2 lying flat (thin along y)
  Points points;
  Triangles triangles;
  add_box(points, triangles, 4., 0.1, 2.);
  const std::vector<View> views = shape_views(points, triangles);
  REQUIRE(views.size() == 3);
  CHECK(views[0].name == "front");
  CHECK(views[1].name == "oblique");
  CHECK(views[2].name == "back");
  // front and back look along the thin axis, y, from either side
  CHECK(std::abs(std::abs(views[0].direction[1]) - 1.) < 1e-6);
  CHECK(views[0].direction[1] == -views[2].direction[1]);
  std::vector<Rgb> colors(triangles.size(), red);
  Render_options options;
  options.view_width = options.view_height = 60;
  const double shape = coverage(render_face_colors(points, triangles, colors, options));
  options.views = default_views();
  const double world = coverage(render_face_colors(points, triangles, colors, options));
  INFO("coverage with the shape's views " << shape << ", with the world's " << world);
  CHECK(shape >= 0.12);
  CHECK(world < 0.12); // edge-on from the front and the back
  // an upright body, thin from front to back (z), keeps the world's front view
  Points upright;
  Triangles upright_triangles;
  add_box(upright, upright_triangles, 1., 4., 0.5);
  const std::vector<View> u = shape_views(upright, upright_triangles);
  const View front = default_views()[0];
  for(int i = 0; i < 3; ++i)
  {
    CHECK(std::abs(u[0].direction[i] - front.direction[i]) < 1e-6);
    CHECK(std::abs(u[0].up[i] - front.up[i]) < 1e-6);
  }
  // the same shape with its faces in another order: the same views
  Triangles reversed(upright_triangles.rbegin(), upright_triangles.rend());
  const View again = shape_views(upright, reversed)[1];
  for(int i = 0; i < 3; ++i)
    CHECK(std::abs(again.direction[i] - u[1].direction[i]) < 1e-9);
  // nothing with an area: the world's views
  CHECK(shape_views({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}}, {{0, 1, 2}})[1].name == "side");
}

TEST_CASE("mismatched sizes and bad indices throw", "[rendering][errors]")
{
  const Points points{{-1, -1, 0}, {1, -1, 0}, {0, 1, 0}};
  const Triangles triangles{{0, 1, 2}};
  const std::string path = unique_temp_path("never_written").string();
  CHECK_THROWS_AS(render_face_colors(points, triangles, {}), SpectralSeg::Invalid_input);
  CHECK_THROWS_AS(render_face_colors(points, triangles, {red, blue}), SpectralSeg::Invalid_input);
  CHECK_THROWS_AS(render_face_colors(points, {{0, 1, 3}}, {red}), SpectralSeg::Invalid_input);
  CHECK_THROWS_AS(render_face_field_png(path, points, triangles, {1.0, 2.0}),
                  SpectralSeg::Invalid_input);
  CHECK_THROWS_AS(render_face_labels_png(path, points, triangles, {}), SpectralSeg::Invalid_input);
  CHECK_THROWS_AS(render_face_labels_png(path, points, {{7, 1, 2}}, {0}), SpectralSeg::Invalid_input);
  CHECK_THROWS_AS(Software_rasterizer(16, 16).render(points, triangles, {red, red},
                                                     front_direction, y_up),
                  SpectralSeg::Invalid_input);
  CHECK_THROWS_AS(Software_rasterizer(16, 16).render(points, triangles, {red},
                                                     {0.0, 0.0, 0.0}, y_up),
                  SpectralSeg::Invalid_input);
  CHECK_THROWS_AS(Software_rasterizer(0, 16), SpectralSeg::Invalid_input);
  CHECK_FALSE(std::filesystem::exists(path));
}

TEST_CASE("write_png writes a PNG with the right header", "[rendering][png]")
{
  const std::filesystem::path path = unique_temp_path("write_png");
  Image img(37, 21);
  img.set_pixel(3, 4, red);
  write_png(path.string(), img);
  const std::vector<unsigned char> bytes = read_bytes(path);
  std::filesystem::remove(path);
  REQUIRE(bytes.size() > 33);
  const unsigned char signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  for(int i = 0; i < 8; ++i)
    CHECK(bytes[i] == signature[i]);
  CHECK(big_endian_u32(bytes, 8) == 13); // IHDR data length
  CHECK(std::string(bytes.begin() + 12, bytes.begin() + 16) == "IHDR");
  CHECK(big_endian_u32(bytes, 16) == 37);
  CHECK(big_endian_u32(bytes, 20) == 21);
  CHECK(bytes[24] == 8); // bit depth
  CHECK(bytes[25] == 2); // colour type RGB
}

TEST_CASE("render_face_field_png writes all views into one PNG", "[rendering][png]")
{
  const std::filesystem::path path = unique_temp_path("field");
  const Points points{{-1, -1, 0}, {1, -1, 0}, {0, 1, 0}, {0, 0, 1}};
  const Triangles triangles{{0, 1, 2}, {0, 1, 3}, {1, 2, 3}, {2, 0, 3}};
  Render_options options;
  options.view_width = 50;
  options.view_height = 40;
  render_face_field_png(path.string(), points, triangles,
                        {0.0, 1.0, std::numeric_limits<double>::infinity(), 0.5}, options);
  const std::vector<unsigned char> bytes = read_bytes(path);
  std::filesystem::remove(path);
  REQUIRE(bytes.size() > 33);
  CHECK(big_endian_u32(bytes, 16) == 150);
  CHECK(big_endian_u32(bytes, 20) == 40);
}

TEST_CASE("write_png reports unwritable paths", "[rendering][png]")
{
  const std::string path =
      (std::filesystem::temp_directory_path() / "spectralseg_no_such_dir_x7" / "out.png").string();
  try
  {
    write_png(path, Image(4, 4));
    FAIL("write_png should have thrown");
  }
  catch(const SpectralSeg::Io_error& e)
  {
    CHECK(std::string(e.what()).find(path) != std::string::npos);
  }
  CHECK_THROWS_AS(write_png(unique_temp_path("empty").string(), Image()), SpectralSeg::Invalid_input);
}
