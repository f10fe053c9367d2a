// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The `spectralseg` Python module (pybind11): numpy vertices and faces in,
// one label (or distance) per face out. One translation unit on purpose:
// CGAL, Eigen and Spectra are slow to compile. doc/python.md is its manual.
//
// Each entry point converts and checks the arrays with the GIL held, then
// releases it for the repair of the soup (the CLI's), the metric and the
// segmentation, and takes it back to build the results. The computation
// runs the library's graph-level functions exactly as `spectralseg segment`
// and `spectralseg distance` do, so that labels equal the CLI's.
#include <SpectralSeg/IO/internal/read_polygon_soup.h>
#include <SpectralSeg/IO/triangle_soup_to_mesh.h>
#include <SpectralSeg/IO/write_face_values.h>
#include <SpectralSeg/Kernels/Any_kernel.h>
#include <SpectralSeg/Kernels/Exponential_kernel.h>
#include <SpectralSeg/Kernels/Gaussian_kernel.h>
#include <SpectralSeg/Metrics/Angular_weight.h>
#include <SpectralSeg/Metrics/Any_weight.h>
#include <SpectralSeg/Metrics/Geodesic_weight.h>
#include <SpectralSeg/Metrics/Part_aware_weight.h>
#include <SpectralSeg/Metrics/VSI_weight.h>
#include <SpectralSeg/Ray_casting/AABB_ray_caster.h>
#ifdef SPECTRALSEG_HAS_EMBREE
#include <SpectralSeg/Ray_casting/Embree_ray_caster.h>
#endif
#include <SpectralSeg/Retrieval/Shape_descriptor.h>
#include <SpectralSeg/automatic_segmentation.h>
#include <SpectralSeg/exceptions.h>
#include <SpectralSeg/segment_hybrid.h>
#include <SpectralSeg/segment_k_way.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <set>
#include <string>
#include <utility>
#include <vector>

#ifndef SPECTRALSEG_VERSION
#define SPECTRALSEG_VERSION "unknown"
#endif

namespace py = pybind11;

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3> Mesh;
typedef std::vector<std::pair<std::string, double>> Timings;

// ---------------------------------------------------------------------------
// Exceptions: spectralseg.Error (a RuntimeError) and its subclasses, which
// also derive from the matching built-in exception.

PyObject* error_type = nullptr;
PyObject* invalid_input_type = nullptr;
PyObject* io_error_type = nullptr;
PyObject* cancelled_type = nullptr;

PyObject* new_exception(py::module_& m, const char* name, PyObject* bases, const char* doc)
{
  const std::string qualified = std::string("spectralseg.") + name;
  PyObject* type = PyErr_NewExceptionWithDoc(qualified.c_str(), doc, bases, nullptr);
  if(type == nullptr)
    throw py::error_already_set();
  m.add_object(name, py::handle(type));
  return type;
}

[[noreturn]] void invalid(const std::string& what) { throw SpectralSeg::Invalid_input(what); }

// ---------------------------------------------------------------------------
// Arrays in.

struct Soup
{
  std::vector<std::array<double, 3>> points;
  std::vector<std::array<std::size_t, 3>> triangles;
};

std::string shape_of(const py::array& a)
{
  std::string s = "(";
  for(py::ssize_t i = 0; i < a.ndim(); ++i)
    s += (i ? ", " : "") + std::to_string(a.shape(i));
  return s + (a.ndim() == 1 ? ",)" : ")");
}

// `vertices` as an (n, 3) array of finite coordinates, `faces` as an (m, 3)
// array of integer vertex indices in [0, n). Called with the GIL held.
Soup soup_from_arrays(const py::object& vertices, const py::object& faces)
{
  const py::module_ np = py::module_::import("numpy");
  const py::array v = np.attr("asarray")(vertices);
  const py::array f = np.attr("asarray")(faces);
  const char vk = v.dtype().kind(), fk = f.dtype().kind();
  if(v.ndim() != 2 || v.shape(1) != 3 || (vk != 'f' && vk != 'i' && vk != 'u'))
    invalid("vertices must be an (n, 3) array of numbers, got shape " + shape_of(v) + " of dtype " +
            std::string(py::str(v.dtype())));
  if(f.ndim() != 2 || f.shape(1) != 3 || (fk != 'i' && fk != 'u' && !(fk == 'f' && f.size() == 0)))
    invalid("faces must be an (m, 3) array of integer vertex indices, got shape " + shape_of(f) + " of dtype " +
            std::string(py::str(f.dtype())));
  if(f.shape(0) == 0)
    invalid("faces is empty: there is nothing to segment");

  Soup soup;
  const auto vd = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(v);
  const auto pv = vd.unchecked<2>();
  soup.points.resize(std::size_t(pv.shape(0)));
  for(py::ssize_t i = 0; i < pv.shape(0); ++i)
    for(py::ssize_t c = 0; c < 3; ++c)
      soup.points[std::size_t(i)][std::size_t(c)] = pv(i, c);

  const std::size_t n = soup.points.size();
  auto index = [&](long double value, py::ssize_t face, py::ssize_t corner) {
    if(!(value >= 0) || value >= static_cast<long double>(n))
      invalid("face " + std::to_string(face) + " has vertex index " + std::to_string(static_cast<long long>(value)) +
              " at corner " + std::to_string(corner) + ", outside [0, " + std::to_string(n) + ")");
    return static_cast<std::size_t>(value);
  };
  soup.triangles.resize(std::size_t(f.shape(0)));
  if(fk == 'u')
  {
    const auto fd = py::array_t<std::uint64_t, py::array::c_style | py::array::forcecast>::ensure(f);
    const auto pf = fd.unchecked<2>();
    for(py::ssize_t i = 0; i < pf.shape(0); ++i)
      for(py::ssize_t c = 0; c < 3; ++c)
        soup.triangles[std::size_t(i)][std::size_t(c)] = index(static_cast<long double>(pf(i, c)), i, c);
  }
  else
  {
    const auto fd = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(f);
    const auto pf = fd.unchecked<2>();
    for(py::ssize_t i = 0; i < pf.shape(0); ++i)
      for(py::ssize_t c = 0; c < 3; ++c)
        soup.triangles[std::size_t(i)][std::size_t(c)] = index(static_cast<long double>(pf(i, c)), i, c);
  }
  return soup;
}

// The named parameters of make_dual_graph(): contact edges between parts
// that touch, specks linked to the nearest part. The defaults are the
// library's, which the CLI uses.
struct Graph_options
{
  bool connect_touching_parts = true;
  double contact_distance = 0.005;
  double speck_area_fraction = 0.01;
};

// The mesh the library segments: the soup repaired as the CLI repairs a
// file (welded, deduplicated, non-manifold edges split, oriented), its
// report, and its dual graph. Built with the GIL released.
struct Input_mesh
{
  Mesh mesh;
  SpectralSeg::IO::Mesh_file_report report;
  SpectralSeg::Dual_graph graph;

  Input_mesh(const Soup& soup, const Graph_options& g)
  {
    report = SpectralSeg::IO::triangle_soup_to_mesh(soup.points, soup.triangles, mesh);
    graph = SpectralSeg::make_dual_graph(mesh, SpectralSeg::parameters::connect_touching_parts(g.connect_touching_parts)
                                                 .contact_distance(g.contact_distance)
                                                 .speck_area_fraction(g.speck_area_fraction));
  }
};

// ---------------------------------------------------------------------------
// Progress, cancellation and Ctrl-C, with the GIL released.

// The library calls its progress callback from the thread that started the
// computation (this one, without the GIL). The bridge takes the GIL to look
// for a pending signal (KeyboardInterrupt) at most every 50 ms, and to call
// the user's callback, if any, at every report. A Python exception (or
// `False` from the callback) stops the computation; the exception is kept
// and raised once the library has unwound.
struct Progress_bridge
{
  py::object user; // None or a callable(stage, fraction)
  bool has_error = false;
  PyObject* type = nullptr;
  PyObject* value = nullptr;
  PyObject* traceback = nullptr;
  std::chrono::steady_clock::time_point last = std::chrono::steady_clock::now();

  explicit Progress_bridge(py::object callback) : user(std::move(callback)) {}
  Progress_bridge(const Progress_bridge&) = delete;
  Progress_bridge& operator=(const Progress_bridge&) = delete;
  ~Progress_bridge()
  {
    Py_XDECREF(type);
    Py_XDECREF(value);
    Py_XDECREF(traceback);
  }

  bool operator()(const std::string& stage, double fraction)
  {
    if(has_error)
      return false;
    const auto now = std::chrono::steady_clock::now();
    if(user.is_none() && now - last < std::chrono::milliseconds(50))
      return true;
    last = now;
    py::gil_scoped_acquire gil;
    if(PyErr_CheckSignals() != 0)
      return keep_error();
    if(user.is_none())
      return true;
    PyObject* r = PyObject_CallFunction(user.ptr(), "sd", stage.c_str(), fraction);
    if(r == nullptr)
      return keep_error();
    const int go = r == Py_None ? 1 : PyObject_IsTrue(r);
    Py_DECREF(r);
    if(go < 0)
      return keep_error();
    return go != 0;
  }

  bool keep_error()
  {
    PyErr_Fetch(&type, &value, &traceback);
    has_error = true;
    return false;
  }

  // with the GIL held, after the computation stopped: the Python exception
  // that stopped it, if any
  void raise_pending()
  {
    if(!has_error)
      return;
    has_error = false;
    PyErr_Restore(type, value, traceback);
    type = value = traceback = nullptr;
    throw py::error_already_set();
  }
};

// Runs `work` with the GIL released and a progress callback wired to the
// bridge; re-raises a Python exception raised while it ran.
template <typename Work>
auto run_without_gil(Progress_bridge& bridge, unsigned threads, Work&& work)
{
  const SpectralSeg::Execution exec(threads, [&bridge](const std::string& s, double f) { return bridge(s, f); });
  try
  {
    py::gil_scoped_release release;
    return work(exec);
  }
  catch(const SpectralSeg::Operation_cancelled&)
  {
    bridge.raise_pending();
    throw;
  }
}

// ---------------------------------------------------------------------------
// Options, as the CLI reads them.

std::string normalized_name(std::string s)
{
  std::replace(s.begin(), s.end(), '_', '-');
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return s;
}

std::string one_of(const char* option, const std::string& value, std::initializer_list<const char*> choices)
{
  const std::string v = normalized_name(value);
  std::string list;
  for(const char* c : choices)
  {
    if(v == c)
      return v;
    list += std::string(list.empty() ? "" : ", ") + "'" + c + "'";
  }
  invalid(std::string(option) + " must be one of " + list + " (got '" + value + "')");
}

std::size_t count(const char* option, long long value, long long lowest, long long highest)
{
  if(value < lowest || value > highest)
    invalid(std::string(option) + " must be an integer in [" + std::to_string(lowest) + ", " + std::to_string(highest) +
            "] (got " + std::to_string(value) + ")");
  return static_cast<std::size_t>(value);
}

double number(const char* option, double value, double lowest, double highest)
{
  if(!(value >= lowest && value <= highest))
    invalid(std::string(option) + " must be a number in [" + std::to_string(lowest) + ", " + std::to_string(highest) +
            "] (got " + std::to_string(value) + ")");
  return value;
}

bool has_embree()
{
#ifdef SPECTRALSEG_HAS_EMBREE
  return true;
#else
  return false;
#endif
}

// a method's name as Python spells it: 'salient-cuts' -> 'salient_cuts'
std::string python_name(std::string name)
{
  std::replace(name.begin(), name.end(), '-', '_');
  return name;
}

// the defaults of the metric keywords and of automatic_segmentation()'s max_k
std::vector<double> default_metric_weights()
{
  return {0.01, 0.195, 0.795};
}
constexpr long long default_automatic_max_k = 20;

long long default_max_measured_faces()
{
  return static_cast<long long>(SpectralSeg::Metrics::VSI::Reference_point_options().max_measured_faces);
}

// whether the part-aware metric's keywords are all at their defaults (the
// weights' default is the caller's): a method that does not use them
// refuses them otherwise; a keyword given its default is not told apart
bool part_aware_keywords_unset(const std::vector<double>& weights, const std::vector<double>& default_weights,
                               const std::string& normalization, double vsi_fraction, long long max_measured_faces,
                               const py::object& ray_caster)
{
  return weights == default_weights && normalization == "p99" && vsi_fraction == 0.01 &&
         max_measured_faces == default_max_measured_faces() && ray_caster.is_none();
}

struct Metric_options
{
  std::string name;
  std::vector<double> weights;
  std::string normalization;
  double vsi_fraction = 0.01;
  std::size_t max_measured_faces = default_max_measured_faces();
  std::string ray_caster;
};

Metric_options metric_options(const std::string& metric, const std::vector<double>& weights,
                              const std::string& normalization, double vsi_fraction, long long max_measured_faces,
                              const py::object& ray_caster)
{
  Metric_options o;
  o.name = one_of("metric", metric, {"part-aware", "blend", "geodesic", "angular", "vsi"});
  if(weights.size() < 2 || weights.size() > 3)
    invalid("weights must hold 2 or 3 coefficients (geodesic, angular[, vsi])");
  bool any = false;
  for(double w : weights)
  {
    number("each of weights", w, 0., 1e6);
    any = any || w > 0.;
  }
  if(!any)
    invalid("weights must not all be 0");
  o.weights = weights;
  o.normalization = one_of("normalization", normalization, {"p99", "max"});
  o.vsi_fraction = number("vsi_fraction", vsi_fraction, 0., 1.);
  o.max_measured_faces = count("max_measured_faces", max_measured_faces, 0, 1000000000);
  if(ray_caster.is_none())
    o.ray_caster = has_embree() ? "embree" : "aabb";
  else
    o.ray_caster = one_of("ray_caster", py::cast<std::string>(ray_caster), {"aabb", "embree"});
  if(o.ray_caster == "embree" && !has_embree())
    invalid("ray_caster 'embree' is not available: this module was built without Embree");
  return o;
}

template <typename RayCaster>
SpectralSeg::Metrics::Any_weight vsi_metric(const Metric_options& o)
{
  using namespace SpectralSeg::Metrics;
  VSI_options vsi;
  vsi.images.sample_fraction = o.vsi_fraction;
  vsi.reference.max_measured_faces = o.max_measured_faces;
  if(o.name == "vsi")
    return VSI_weight<RayCaster>(vsi);
  const double gamma = o.weights.size() > 2 ? o.weights[2] : 0.;
  return Part_aware_weight<RayCaster>(o.weights[0], o.weights[1], gamma, vsi, 0.001,
                                      o.normalization == "max" ? Normalization::maximum()
                                                               : Normalization::quantile(0.99));
}

SpectralSeg::Metrics::Any_weight make_metric(const Metric_options& o)
{
  if(o.name == "geodesic")
    return SpectralSeg::Metrics::Geodesic_weight();
  if(o.name == "angular")
    return SpectralSeg::Metrics::Angular_weight();
#ifdef SPECTRALSEG_HAS_EMBREE
  if(o.ray_caster == "embree")
    return vsi_metric<SpectralSeg::Ray_casting::Embree_ray_caster>(o);
#endif
  return vsi_metric<SpectralSeg::Ray_casting::AABB_ray_caster>(o);
}

Graph_options graph_options(bool connect_touching_parts, double contact_distance, double speck_area_fraction)
{
  Graph_options g;
  g.connect_touching_parts = connect_touching_parts;
  g.contact_distance = number("contact_distance", contact_distance, 0., 1.);
  g.speck_area_fraction = number("speck_area_fraction", speck_area_fraction, 0., 1.);
  return g;
}

struct K_way_settings
{
  std::string kernel;
  SpectralSeg::K_way_options options;
};

// 'exponential' or 'gaussian' (checked by k_way_settings()), behind one type:
// the methods are compiled once for both
SpectralSeg::Kernels::Any_kernel chosen_kernel(const std::string& name)
{
  if(name == "gaussian")
    return SpectralSeg::Kernels::Gaussian_kernel();
  return SpectralSeg::Kernels::Exponential_kernel();
}

K_way_settings k_way_settings(const std::string& kernel, const std::string& sampling, long long samples, long long seed,
                              bool boundary_enhancement, long long extra_clusters)
{
  K_way_settings s;
  s.kernel = one_of("kernel", kernel, {"exponential", "gaussian"});
  const std::string m = one_of("sampling", sampling, {"auto", "exact", "nystrom", "gamma"});
  s.options.embedding.method = m == "exact"  ? SpectralSeg::Embedding::Method::exact
                               : m == "auto" ? SpectralSeg::Embedding::Method::automatic
                                             : SpectralSeg::Embedding::Method::nystrom;
  if(m == "gamma")
    s.options.embedding.sampling = SpectralSeg::Embedding::Sampling_method::gamma;
  s.options.embedding.samples = count("samples", samples, 0, 1000000);
  s.options.embedding.seed = static_cast<unsigned>(count("seed", seed, 0, std::numeric_limits<std::uint32_t>::max()));
  s.options.extra_clusters = count("extra_clusters", extra_clusters, 0, 1000);
  s.options.boundary_enhancement = boundary_enhancement;
  return s;
}

// ---------------------------------------------------------------------------
// Results out.

py::array_t<std::int64_t> labels_array(const std::vector<int>& labels)
{
  py::array_t<std::int64_t> a(static_cast<py::ssize_t>(labels.size()));
  auto p = a.mutable_unchecked<1>();
  for(std::size_t i = 0; i < labels.size(); ++i)
    p(py::ssize_t(i)) = labels[i];
  return a;
}

py::array_t<double> values_array(const std::vector<double>& values)
{
  py::array_t<double> a(static_cast<py::ssize_t>(values.size()));
  auto p = a.mutable_unchecked<1>();
  for(std::size_t i = 0; i < values.size(); ++i)
    p(py::ssize_t(i)) = values[i];
  return a;
}

// What every report holds: faces, repairs, timings.
py::dict base_report(const Input_mesh& m, const Timings& timings, unsigned threads)
{
  const SpectralSeg::IO::Mesh_file_report& r = m.report;
  py::dict d;
  d["faces"] = r.input_faces;
  d["mesh_faces"] = m.graph.number_of_faces();
  py::dict repairs;
  repairs["merged_vertices"] = r.merged_vertices;
  repairs["invalid_faces"] = r.invalid_faces;
  repairs["duplicate_faces"] = r.duplicate_faces;
  repairs["non_manifold_edges"] = r.non_manifold_edges;
  repairs["split_vertices"] = r.split_vertices;
  d["repairs"] = repairs;
  py::list warnings;
  for(const std::string& w : r.warnings)
    warnings.append(w);
  d["warnings"] = warnings;
  d["closed"] = r.closed;
  d["threads"] = threads;
  py::dict t;
  double total = 0.;
  for(const auto& st : timings)
  {
    const double before = t.contains(st.first) ? py::cast<double>(t[py::str(st.first)]) : 0.;
    t[py::str(st.first)] = before + st.second;
    total += st.second;
  }
  t["total"] = total;
  d["timings"] = t;
  return d;
}

void add_segments(py::dict& d, const Input_mesh& m, const std::vector<int>& labels)
{
  const std::size_t segments =
    labels.empty() ? 0 : std::size_t(*std::max_element(labels.begin(), labels.end()) + 1);
  d["segments"] = segments;
  std::vector<double> areas(segments, 0.);
  std::vector<std::size_t> faces(segments, 0);
  for(std::size_t f = 0; f < labels.size(); ++f)
  {
    areas[std::size_t(labels[f])] += m.graph.geometry().areas[f];
    ++faces[std::size_t(labels[f])];
  }
  py::list list;
  for(std::size_t s = 0; s < segments; ++s)
  {
    py::dict e;
    e["label"] = s;
    e["faces"] = faces[s];
    e["area"] = areas[s];
    list.append(e);
  }
  d["segment_list"] = list;
}

py::object labels_result(const Input_mesh& m, const std::vector<int>& mesh_labels, py::dict report, bool want_report)
{
  // segments numbered in the order of the input's faces
  const std::vector<int> labels = SpectralSeg::IO::number_segments_in_input_order(m.report, mesh_labels);
  py::array_t<std::int64_t> out = labels_array(SpectralSeg::IO::values_in_input_order(m.report, labels, -1));
  if(!want_report)
    return std::move(out);
  add_segments(report, m, labels);
  return py::make_tuple(out, report);
}

// Reads the timings as the CLI does: metric first, then the method's stages.
struct Timer
{
  std::chrono::steady_clock::time_point t0 = std::chrono::steady_clock::now();
  Timings timings;
  void lap(const std::string& stage)
  {
    const auto now = std::chrono::steady_clock::now();
    timings.emplace_back(stage, std::chrono::duration<double>(now - t0).count());
    t0 = now;
  }
};

// ---------------------------------------------------------------------------
// Entry points.

const char* const segmentation_method_doc = R"doc(
Common keyword arguments (the CLI's options of the same names):
    metric: 'part-aware' (default; geodesic + angular + VSI blend), 'geodesic', 'angular' or 'vsi'
    weights: part-aware coefficients (geodesic, angular[, vsi]), default (0.01, 0.195, 0.795)
    normalization: 'p99' (default) or 'max' (the thesis)
    vsi_fraction: fraction of the faces whose shape image is ray-cast, default 0.01
    max_measured_faces: at most this many faces cast their cone of rays for their
        reference point, the others take their neighbours' depth; default 100000, 0: every face
    ray_caster: 'embree' (default when built with Embree) or 'aabb'
    kernel: 'exponential' (default) or 'gaussian'
    sampling: 'auto' (default: exact up to 2000 faces, Nystrom above), 'exact', 'nystrom' or 'gamma'
    samples: Nystrom samples, 0 (default) for one more than the clusters
    seed: seed of the sampling's start face, default 0
    boundary_enhancement: refine the boundaries by graph cut, default True
    threads: 0 (default) for all hardware threads; the labels do not depend on it
    progress: None or a callable(stage: str, fraction: float); returning False cancels (CancelledError)
    report: if True, return (labels, report dict) instead of labels
    connect_touching_parts: join parts that touch without sharing an edge by contact edges, and link
        specks to the nearest part (SpectralSeg::make_dual_graph()), default True; False keeps only
        the mesh edges, so that every separate piece is at least one segment (the thesis's graph)
    contact_distance: how close vertices of different pieces must be to join them, as a fraction of
        the bounding-box diagonal, in [0, 1], default 0.005
    speck_area_fraction: pieces under this fraction of the area that touch nothing are linked to the
        nearest part, in [0, 1] (0: none), default 0.01
    (the last three are not options of the tool, which uses their defaults)
)doc";

// K_way_options::alternative_extra_clusters, as Python integers
std::vector<long long> default_alternative_extra_clusters()
{
  const SpectralSeg::K_way_options defaults;
  return std::vector<long long>(defaults.alternative_extra_clusters.begin(), defaults.alternative_extra_clusters.end());
}

py::object k_way_segmentation(const py::object& vertices, const py::object& faces, long long k, const std::string& metric,
                              const std::vector<double>& weights, const std::string& normalization,
                              double vsi_fraction, long long max_measured_faces, const py::object& ray_caster,
                              const std::string& kernel,
                              const std::string& sampling, long long samples, long long seed,
                              bool boundary_enhancement, long long extra_clusters,
                              const std::vector<long long>& alternative_extra_clusters,
                              long long contrast_merge_clusters, long long min_candidate_clusters,
                              double flat_seam_angle, long long threads, const py::object& progress, bool report,
                              bool connect_touching_parts, double contact_distance, double speck_area_fraction)
{
  const Soup soup = soup_from_arrays(vertices, faces);
  const Graph_options go = graph_options(connect_touching_parts, contact_distance, speck_area_fraction);
  const std::size_t kk = count("k", k, 1, 100000);
  const Metric_options mo = metric_options(metric, weights, normalization, vsi_fraction, max_measured_faces,
                                           ray_caster);
  K_way_settings ks = k_way_settings(kernel, sampling, samples, seed, boundary_enhancement, extra_clusters);
  ks.options.alternative_extra_clusters.clear();
  for(long long e : alternative_extra_clusters)
    ks.options.alternative_extra_clusters.push_back(count("alternative_extra_clusters", e, 0, 1000));
  ks.options.contrast_merge_clusters = count("contrast_merge_clusters", contrast_merge_clusters, 0, 1000);
  ks.options.min_candidate_clusters = count("min_candidate_clusters", min_candidate_clusters, 0, 1000);
  if(!(flat_seam_angle >= 0. && flat_seam_angle < 180.))
    invalid("flat_seam_angle must be a number of degrees in [0, 180)");
  ks.options.flat_seam_angle = flat_seam_angle;
  const unsigned t = static_cast<unsigned>(count("threads", threads, 0, 4096));
  Progress_bridge bridge(progress);
  struct Out
  {
    std::unique_ptr<Input_mesh> m;
    SpectralSeg::K_way_result r;
    std::string metric;
    Timings timings;
    unsigned threads = 0;
  };
  Out out = run_without_gil(bridge, t, [&](const SpectralSeg::Execution& exec) {
    Out o;
    Timer timer;
    o.m = std::make_unique<Input_mesh>(soup, go);
    timer.lap("read");
    const std::size_t n = o.m->graph.number_of_faces();
    if(kk > n)
      invalid("k = " + std::to_string(kk) + " is larger than the number of faces (" + std::to_string(n) + ")");
    const SpectralSeg::Metrics::Any_weight w = make_metric(mo);
    o.metric = w.name();
    const SpectralSeg::Weighted_dual_graph weighted(o.m->graph, SpectralSeg::Metrics::metric_values(w, o.m->graph, exec));
    timer.lap("metric");
    o.r = SpectralSeg::segment_k_way(weighted, kk, ks.options.with_kernel(chosen_kernel(ks.kernel)), exec);
    o.timings = timer.timings;
    o.timings.insert(o.timings.end(), o.r.timings.begin(), o.r.timings.end());
    o.threads = exec.threads();
    return o;
  });
  py::dict d = base_report(*out.m, out.timings, out.threads);
  d["k"] = kk;
  d["metric"] = out.metric;
  d["kernel"] = ks.kernel;
  d["embedding"] = out.r.embedding.exact ? "exact" : "nystrom";
  d["samples"] = out.r.embedding.samples;
  d["kernel_width"] = out.r.embedding.kernel_width;
  d["graph_cut"] = boundary_enhancement;
  // the kept over-segmentation, as in the tool's JSON report
  d["extra_clusters"] = out.r.extra_clusters;
  d["merge"] = out.r.contrast_merge ? "contrast" : "concave";
  if(!ks.options.alternative_extra_clusters.empty() || ks.options.contrast_merge_clusters > 0)
    d["concave_normalized_cut"] = out.r.normalized_cut;
  if(!out.r.candidates.empty())
  { // every over-segmentation tried, as in the tool's JSON report
    py::list candidates;
    for(const SpectralSeg::K_way_candidate& c : out.r.candidates)
    {
      py::dict x;
      x["extra_clusters"] = c.extra_clusters;
      x["merge"] = c.contrast_merge ? "contrast" : "concave";
      x["segments"] = c.number_of_segments;
      x["concave_normalized_cut_before_graph_cut"] = c.normalized_cut_before_graph_cut;
      x["concave_normalized_cut"] = c.normalized_cut;
      x["kept"] = c.kept;
      candidates.append(x);
    }
    d["candidates"] = candidates;
  }
  return labels_result(*out.m, out.r.labels, d, report);
}

// one node and its subtree; `cuts`: the salient-cut method's, else merges
py::dict hierarchy_dict(const SpectralSeg::Part_hierarchy& h, std::size_t node, bool cuts)
{
  const SpectralSeg::Part_node& n = h.nodes[node];
  py::dict d;
  d["faces"] = n.faces.size();
  d["area"] = n.area;
  d["depth"] = n.depth;
  if(cuts)
    d["tested"] = n.tested;
  if(n.tested)
  {
    d["test"] = SpectralSeg::Segmentability::test_name(n.test);
    d["score"] = n.score;
    py::dict scores;
    const char* names[] = {"L", "L-MDS", "M", "M-MDS"};
    for(std::size_t t = 0; t < 4; ++t)
      if(std::isfinite(n.scores[t]))
        scores[names[t]] = n.scores[t];
    d["scores"] = scores;
  }
  if(!n.is_leaf())
  {
    d["cut"] = n.cut_order;
    if(cuts)
      d["salience"] = n.cut_salience;
    else
      d["boundary_strength"] = n.boundary_strength;
    d["children"] = py::make_tuple(hierarchy_dict(h, n.children[0], cuts), hierarchy_dict(h, n.children[1], cuts));
  }
  return d;
}

// the report's "hierarchy", as in the tool's JSON report
py::dict hierarchy_report(const SpectralSeg::Part_hierarchy& h, bool cuts)
{
  py::dict d;
  d["kind"] = cuts ? "cuts" : "merges";
  d["chosen_cuts"] = h.chosen_cuts;
  d["leaves"] = h.number_of_leaves();
  py::list roots;
  for(std::size_t root : h.roots)
    roots.append(hierarchy_dict(h, root, cuts));
  d["roots"] = roots;
  return d;
}

// k chosen by the library: the three methods of `--k auto`.
py::object automatic(const py::object& vertices, const py::object& faces, const std::string& method_name,
                     long long max_k, const py::object& min_boundary_contrast, double eta, bool structure_only,
                     const py::object& min_part_area, const py::object& max_parts, const py::object& parts,
                     const py::object& depth,
                     const std::string& metric, const std::vector<double>& weights, const std::string& normalization,
                     double vsi_fraction, long long max_measured_faces, const py::object& ray_caster,
                     const std::string& kernel,
                     const std::string& sampling, long long samples, long long seed, bool boundary_enhancement,
                     long long threads, const py::object& progress, bool report, bool connect_touching_parts,
                     double contact_distance, double speck_area_fraction)
{
  const Soup soup = soup_from_arrays(vertices, faces);
  const Graph_options go = graph_options(connect_touching_parts, contact_distance, speck_area_fraction);
  const std::string method =
    one_of("method", method_name, {"contrast-merge", "concave-merge", "salient-cuts", "salient-cuts-thesis"});
  const bool salient = method == "salient-cuts" || method == "salient-cuts-thesis";
  const std::size_t max_clusters = count("max_k", max_k, 2, 100000);
  const double contrast =
    min_boundary_contrast.is_none() ? 0. : number("min_boundary_contrast", py::cast<double>(min_boundary_contrast), 0., 1e6);
  typedef SpectralSeg::Automatic_segmentation_options<> Salient_options;
  Salient_options so = method == "salient-cuts-thesis" ? Salient_options::thesis() : Salient_options();
  so.segmentability.threshold = number("eta", eta, 0., 1.);
  so.segmentability.structure_only = structure_only;
  if(!min_part_area.is_none())
    so.min_part_area_fraction = number("min_part_area", py::cast<double>(min_part_area), 0., 0.49);
  if(!max_parts.is_none())
    so.max_parts = count("max_parts", py::cast<long long>(max_parts), 0, 1000000);
  const std::size_t keep_parts = parts.is_none() ? 0 : count("parts", py::cast<long long>(parts), 1, 1000000);
  const std::size_t keep_depth = depth.is_none() ? std::numeric_limits<std::size_t>::max()
                                                 : count("depth", py::cast<long long>(depth), 0, 1000000);
  if(!salient && (!depth.is_none() || eta != Salient_options().segmentability.threshold ||
                  structure_only != Salient_options().segmentability.structure_only || !min_part_area.is_none() ||
                  !max_parts.is_none()))
    invalid("eta, structure_only, min_part_area, max_parts and depth apply to method='salient_cuts', not '" +
            python_name(method) + "'");
  // the salient cuts weigh the dual graph themselves and make no embedding:
  // the metric and k-way keywords are refused rather than ignored (as the
  // CLI refuses their options)
  if(salient && (metric != "part-aware" ||
                 !part_aware_keywords_unset(weights, default_metric_weights(), normalization, vsi_fraction,
                                            max_measured_faces, ray_caster) ||
                 kernel != "exponential" || sampling != "auto" || samples != 0 || seed != 0 || !boundary_enhancement ||
                 max_k != default_automatic_max_k || !min_boundary_contrast.is_none()))
    invalid("metric, weights, normalization, vsi_fraction, max_measured_faces, ray_caster, kernel, sampling, samples, "
            "seed, boundary_enhancement, max_k and min_boundary_contrast do not apply to method='" +
            python_name(method) + "': the salient cuts use none of the metric and k-way options");
  const Metric_options mo = metric_options(metric, weights, normalization, vsi_fraction, max_measured_faces,
                                           ray_caster);
  const K_way_settings ks = k_way_settings(kernel, sampling, samples, seed, boundary_enhancement,
                                           static_cast<long long>(SpectralSeg::K_way_options().extra_clusters));
  const unsigned t = static_cast<unsigned>(count("threads", threads, 0, 4096));
  Progress_bridge bridge(progress);
  struct Out
  {
    std::unique_ptr<Input_mesh> m;
    std::vector<int> labels;
    SpectralSeg::K_way_result r;
    SpectralSeg::Automatic_segmentation_result a;
    std::string metric;
    Timings timings;
    unsigned threads = 0;
  };
  Out out = run_without_gil(bridge, t, [&](const SpectralSeg::Execution& exec) {
    Out o;
    Timer timer;
    o.m = std::make_unique<Input_mesh>(soup, go);
    timer.lap("read");
    o.threads = exec.threads();
    const SpectralSeg::Dual_graph& graph = o.m->graph;
    const std::size_t n = graph.number_of_faces();
    if(salient)
    {
      o.a = SpectralSeg::segment_automatically(graph, SpectralSeg::sequence_weights(graph, exec), so, exec);
      o.labels = o.a.labels;
      if(keep_parts > 0)
        o.labels = o.a.hierarchy.labels_with_parts(keep_parts);
      if(keep_depth != std::numeric_limits<std::size_t>::max())
      {
        const std::vector<int> at_depth = o.a.hierarchy.labels_at_depth(keep_depth);
        if(keep_parts == 0 || std::set<int>(at_depth.begin(), at_depth.end()).size() <
                                std::set<int>(o.labels.begin(), o.labels.end()).size())
          o.labels = at_depth;
      }
      o.timings = timer.timings;
      o.timings.insert(o.timings.end(), o.a.timings.begin(), o.a.timings.end());
      return o;
    }
    if(n < 2)
      invalid("automatic segmentation needs at least 2 faces");
    const SpectralSeg::Metrics::Any_weight w = make_metric(mo);
    o.metric = w.name();
    const SpectralSeg::Weighted_dual_graph weighted(graph, SpectralSeg::Metrics::metric_values(w, graph, exec));
    timer.lap("metric");
    auto run = [&](const auto& kern) {
      typedef std::decay_t<decltype(kern)> K;
      SpectralSeg::Basic_K_way_automatic_options<K> automatic;
      automatic.k_way = ks.options.with_kernel(kern);
      automatic.max_k = std::max<std::size_t>(2, std::min(max_clusters, n - 1));
      if(contrast > 0.)
        automatic.min_boundary_contrast = contrast;
      automatic.parts = keep_parts;
      if(method == "contrast-merge")
      {
        SpectralSeg::Basic_hybrid_options<K> hybrid;
        hybrid.k_way = automatic.k_way;
        hybrid.clusters = automatic.max_k;
        if(contrast > 0.)
          hybrid.min_boundary_contrast = contrast;
        hybrid.parts = keep_parts;
        return SpectralSeg::segment_hybrid(weighted, hybrid, exec);
      }
      return SpectralSeg::segment_k_way_automatic(weighted, automatic, exec);
    };
    o.r = run(chosen_kernel(ks.kernel));
    o.labels = o.r.labels;
    o.timings = timer.timings;
    o.timings.insert(o.timings.end(), o.r.timings.begin(), o.r.timings.end());
    return o;
  });
  py::dict d = base_report(*out.m, out.timings, out.threads);
  d["method"] = method;
  if(salient)
  {
    d["eta"] = so.segmentability.threshold;
    d["structure_only"] = structure_only;
    d["min_part_area"] = so.min_part_area_fraction;
    d["parts_found"] = out.a.number_of_segments;
    d["hierarchy"] = hierarchy_report(out.a.hierarchy, true);
  }
  else
  {
    d["metric"] = out.metric;
    d["kernel"] = ks.kernel;
    d["embedding"] = out.r.embedding.exact ? "exact" : "nystrom";
    d["samples"] = out.r.embedding.samples;
    d["kernel_width"] = out.r.embedding.kernel_width;
    d["graph_cut"] = boundary_enhancement;
    d["hierarchy"] = hierarchy_report(out.r.hierarchy, false);
  }
  return labels_result(*out.m, out.labels, d, report);
}

py::object face_distances(const py::object& vertices, const py::object& faces, const py::object& sources,
                          const std::string& metric, const std::vector<double>& weights,
                          const std::string& normalization, double vsi_fraction, long long max_measured_faces,
                          const py::object& ray_caster,
                          long long threads, const py::object& progress, bool return_nearest,
                          bool connect_touching_parts, double contact_distance, double speck_area_fraction)
{
  const Soup soup = soup_from_arrays(vertices, faces);
  const Graph_options go = graph_options(connect_touching_parts, contact_distance, speck_area_fraction);
  std::vector<long long> from;
  const py::array s = py::module_::import("numpy").attr("asarray")(sources);
  if(s.ndim() > 1 || (s.dtype().kind() != 'i' && s.dtype().kind() != 'u') || s.size() == 0)
    invalid("sources must be a face index or a non-empty sequence of face indices");
  const auto si = py::array_t<long long, py::array::c_style | py::array::forcecast>::ensure(s);
  for(py::ssize_t i = 0; i < si.size(); ++i)
    from.push_back(si.data()[i]);
  const Metric_options mo = metric_options(metric, weights, normalization, vsi_fraction, max_measured_faces,
                                           ray_caster);
  const unsigned t = static_cast<unsigned>(count("threads", threads, 0, 4096));
  Progress_bridge bridge(progress);
  struct Out
  {
    std::unique_ptr<Input_mesh> m;
    SpectralSeg::Nearest_source_distances d;
  };
  Out out = run_without_gil(bridge, t, [&](const SpectralSeg::Execution& exec) {
    Out o;
    o.m = std::make_unique<Input_mesh>(soup, go);
    const SpectralSeg::IO::Mesh_file_report& r = o.m->report;
    std::vector<SpectralSeg::Dual_graph::size_type> ids;
    for(long long f : from)
    {
      if(f < 0 || static_cast<std::size_t>(f) >= r.face_of_input_face.size())
        invalid("source face " + std::to_string(f) + " does not exist: there are " +
                std::to_string(r.face_of_input_face.size()) + " faces");
      const std::size_t mf = r.face_of_input_face[std::size_t(f)];
      if(mf == SpectralSeg::IO::Mesh_file_report::no_face)
        invalid("source face " + std::to_string(f) + " was dropped (fewer than three distinct vertices)");
      ids.push_back(static_cast<SpectralSeg::Dual_graph::size_type>(mf));
    }
    const SpectralSeg::Metrics::Any_weight w = make_metric(mo);
    exec.report(w.name() + " weights", 0.);
    const SpectralSeg::Weighted_dual_graph weighted(o.m->graph, SpectralSeg::Metrics::metric_values(w, o.m->graph, exec));
    exec.report(w.name() + " weights", 1.);
    exec.report("dijkstra", 0.);
    o.d = weighted.distances(ids);
    exec.report("dijkstra", 1.);
    return o;
  });
  py::array_t<double> d = values_array(SpectralSeg::IO::values_in_input_order(
    out.m->report, out.d.distance, std::numeric_limits<double>::quiet_NaN()));
  if(!return_nearest)
    return std::move(d);
  std::vector<int> nearest(out.d.nearest_source.size());
  for(std::size_t f = 0; f < nearest.size(); ++f)
    nearest[f] = out.d.nearest_source[f] == SpectralSeg::Nearest_source_distances::unreachable
                   ? -1
                   : static_cast<int>(out.d.nearest_source[f]);
  return py::make_tuple(d, labels_array(SpectralSeg::IO::values_in_input_order(out.m->report, nearest, -1)));
}

py::tuple read_mesh(const std::string& path)
{
  SpectralSeg::IO::internal::Polygon_soup soup;
  {
    py::gil_scoped_release release;
    soup = SpectralSeg::IO::internal::read_polygon_soup(path);
  }
  const std::size_t faces = soup.number_of_faces();
  for(std::size_t f = 0; f < faces; ++f)
    if(soup.face_size(f) != 3)
      invalid("'" + path + "': face " + std::to_string(f) + " has " + std::to_string(soup.face_size(f)) +
              " vertices; read_mesh() returns triangles only (triangulate the mesh first, or use the "
              "spectralseg command-line tool, which triangulates polygons)");
  py::array_t<double> v({static_cast<py::ssize_t>(soup.points.size()), py::ssize_t(3)});
  auto pv = v.mutable_unchecked<2>();
  for(std::size_t i = 0; i < soup.points.size(); ++i)
    for(std::size_t c = 0; c < 3; ++c)
      pv(py::ssize_t(i), py::ssize_t(c)) = soup.points[i][c];
  py::array_t<std::int64_t> f({static_cast<py::ssize_t>(faces), py::ssize_t(3)});
  auto pf = f.mutable_unchecked<2>();
  for(std::size_t i = 0; i < faces; ++i)
    for(std::size_t c = 0; c < 3; ++c)
      pf(py::ssize_t(i), py::ssize_t(c)) = static_cast<std::int64_t>(soup.face(i)[c]);
  return py::make_tuple(v, f);
}

} // namespace

// ---------------------------------------------------------------------------
// Shape retrieval (thesis 3.6): descriptors as dicts, chi-square, ranking.

py::dict descriptor_dict(const SpectralSeg::Retrieval::Shape_descriptor& d)
{
  py::dict out;
  out["metric"] = d.metric;
  out["histogram"] = values_array(d.histogram);
  out["range"] = d.range;
  out["mean_distance"] = d.mean_distance;
  out["sources"] = d.sources;
  return out;
}

SpectralSeg::Retrieval::Shape_descriptor descriptor_of_dict(const py::object& o)
{
  if(!py::isinstance<py::dict>(o))
    invalid("a descriptor must be a dict returned by shape_descriptor()");
  const py::dict d = o.cast<py::dict>();
  for(const char* key : {"metric", "histogram", "range"})
    if(!d.contains(key))
      invalid(std::string("a descriptor needs the key '") + key + "' (as returned by shape_descriptor())");
  SpectralSeg::Retrieval::Shape_descriptor r;
  r.metric = py::cast<std::string>(d["metric"]);
  r.histogram = py::cast<std::vector<double>>(py::module_::import("numpy").attr("asarray")(d["histogram"], "float64").attr("tolist")());
  r.range = py::cast<double>(d["range"]);
  return r;
}

py::dict shape_descriptor(const py::object& vertices, const py::object& faces, const std::string& metric,
                          const std::vector<double>& weights, const std::string& normalization, double vsi_fraction,
                          long long max_measured_faces,
                          const py::object& ray_caster, long long bins, long long sources, double range,
                          long long threads, const py::object& progress, bool connect_touching_parts,
                          double contact_distance, double speck_area_fraction)
{
  const Soup soup = soup_from_arrays(vertices, faces);
  const Graph_options go = graph_options(connect_touching_parts, contact_distance, speck_area_fraction);
  const std::string name = one_of("metric", metric, {"part-aware", "geodesic", "euclidean"});
  if(weights.size() != 3)
    invalid("weights must hold 3 coefficients (geodesic, angular, vsi)");
  if(name != "part-aware" && !part_aware_keywords_unset(weights, std::vector<double>{0.02, 0., 0.98}, normalization,
                                                        vsi_fraction, max_measured_faces, ray_caster))
    invalid("weights, normalization, vsi_fraction, max_measured_faces and ray_caster apply to metric 'part-aware', "
            "not '" + name + "'");
  const Metric_options mo = metric_options(name == "euclidean" ? "geodesic" : name, weights, normalization,
                                           vsi_fraction, max_measured_faces, ray_caster);
  SpectralSeg::Retrieval::Descriptor_options options;
  options.bins = count("bins", bins, 2, 100000);
  options.sources = count("sources", sources, 1, 100000);
  options.range = number("range", range, 1e-3, 1e3);
  const unsigned t = static_cast<unsigned>(count("threads", threads, 0, 4096));
  Progress_bridge bridge(progress);
  const SpectralSeg::Retrieval::Shape_descriptor d = run_without_gil(bridge, t, [&](const SpectralSeg::Execution& exec) {
    const Input_mesh m(soup, go);
    if(name == "euclidean")
      return SpectralSeg::Retrieval::shape_descriptor(m.graph, SpectralSeg::Retrieval::Euclidean_distance(), options, exec);
    const SpectralSeg::Metrics::Any_weight w = make_metric(mo);
    exec.report(w.name() + " weights", 0.);
    const SpectralSeg::Weighted_dual_graph weighted(m.graph, SpectralSeg::Metrics::metric_values(w, m.graph, exec));
    exec.report(w.name() + " weights", 1.);
    return SpectralSeg::Retrieval::shape_descriptor(weighted, w.name(), options, exec);
  });
  return descriptor_dict(d);
}

double chi_square_distance(const py::object& a, const py::object& b)
{
  return SpectralSeg::Retrieval::chi_square_distance(descriptor_of_dict(a), descriptor_of_dict(b));
}

py::list rank_shapes(const py::object& query, const py::iterable& database)
{
  std::vector<SpectralSeg::Retrieval::Shape_descriptor> db;
  for(const py::handle& h : database)
    db.push_back(descriptor_of_dict(py::reinterpret_borrow<py::object>(h)));
  py::list out;
  for(const SpectralSeg::Retrieval::Ranked_shape& r : SpectralSeg::Retrieval::rank_shapes(descriptor_of_dict(query), db))
    out.append(py::make_tuple(r.index, r.distance));
  return out;
}

PYBIND11_MODULE(spectralseg, m)
{
  m.doc() = R"doc(Part-aware spectral segmentation of triangle meshes (SpectralSeg).

Vertices are an (n, 3) float array, faces an (m, 3) integer array of vertex
indices (as numpy, trimesh, Open3D and libigl hold them). The soup is
repaired as the spectralseg command-line tool repairs a file (identical
vertices welded, duplicate and degenerate faces dropped, non-manifold edges
split, closed meshes oriented outward); pieces that touch without sharing
an edge are joined, and specks linked to the nearest part, unless
connect_touching_parts=False. Results have one entry per row of `faces`,
-1 (labels) or nan (distances) for a dropped face. The GIL is released
while computing; Ctrl-C interrupts.)doc";
  m.attr("__version__") = SPECTRALSEG_VERSION;
  m.attr("has_embree") = has_embree();

  error_type = new_exception(m, "Error", PyExc_RuntimeError,
                             "Base class of the errors of the library (a RuntimeError).");
  const py::tuple invalid_bases = py::make_tuple(py::handle(error_type), py::handle(PyExc_ValueError));
  invalid_input_type = new_exception(m, "InvalidInputError", invalid_bases.ptr(),
                                     "An unusable mesh or option (also a ValueError).");
  const py::tuple io_bases = py::make_tuple(py::handle(error_type), py::handle(PyExc_OSError));
  io_error_type = new_exception(m, "IoError", io_bases.ptr(),
                                "A file that cannot be read, or is malformed (also an OSError).");
  cancelled_type = new_exception(m, "CancelledError", error_type,
                                 "The progress callback returned False.");
  py::register_exception_translator([](std::exception_ptr p) {
    try
    {
      if(p)
        std::rethrow_exception(p);
    }
    catch(const SpectralSeg::Invalid_input& e)
    {
      PyErr_SetString(invalid_input_type, e.what());
    }
    catch(const SpectralSeg::Io_error& e)
    {
      PyErr_SetString(io_error_type, e.what());
    }
    catch(const SpectralSeg::Operation_cancelled& e)
    {
      PyErr_SetString(cancelled_type, e.what());
    }
    catch(const SpectralSeg::Error& e)
    {
      PyErr_SetString(error_type, e.what());
    }
  });

  const std::vector<double> default_weights = default_metric_weights();
  const SpectralSeg::Automatic_segmentation_options<> automatic_defaults;

  m.def("read_mesh", &read_mesh, py::arg("path"),
        R"doc(read_mesh(path) -> (vertices, faces)

The vertices ((n, 3) float64) and triangles ((m, 3) int64) of an OFF, OBJ,
PLY or STL file, as the file gives them, unrepaired: the segmentation
functions repair them as the command-line tool does, so their labels match
the tool's labels file line for line. Raises IoError for a missing or
malformed file, InvalidInputError for a face that is not a triangle.)doc");

  m.def("k_way_segmentation", &k_way_segmentation, py::arg("vertices"), py::arg("faces"), py::arg("k"),
        py::kw_only(), py::arg("metric") = "part-aware", py::arg("weights") = default_weights,
        py::arg("normalization") = "p99", py::arg("vsi_fraction") = 0.01,
        py::arg("max_measured_faces") = default_max_measured_faces(), py::arg("ray_caster") = py::none(),
        py::arg("kernel") = "exponential", py::arg("sampling") = "auto", py::arg("samples") = 0,
        py::arg("seed") = 0, py::arg("boundary_enhancement") = true,
        py::arg("extra_clusters") = static_cast<long long>(SpectralSeg::K_way_options().extra_clusters),
        py::arg("alternative_extra_clusters") = default_alternative_extra_clusters(),
        py::arg("contrast_merge_clusters") =
          static_cast<long long>(SpectralSeg::K_way_options().contrast_merge_clusters),
        py::arg("min_candidate_clusters") =
          static_cast<long long>(SpectralSeg::K_way_options().min_candidate_clusters),
        py::arg("flat_seam_angle") = SpectralSeg::K_way_options().flat_seam_angle,
        py::arg("threads") = 0, py::arg("progress") = py::none(), py::arg("report") = false,
        py::arg("connect_touching_parts") = true, py::arg("contact_distance") = 0.005,
        py::arg("speck_area_fraction") = 0.01,
        (std::string(R"doc(k_way_segmentation(vertices, faces, k, **options) -> labels

Segments the mesh into k parts by spectral clustering of the part-aware
metric (SpectralSeg::segment_k_way(), `spectralseg segment --k K`).
Returns one label per row of `faces`, in [0, segments), -1 for a dropped
face; segments is k, more if the mesh has pieces that stay apart (see
connect_touching_parts).

extra_clusters: K-means makes k + extra_clusters clusters, then the weakest
    boundaries are merged until k are left (default 2)
alternative_extra_clusters: other numbers of extra clusters to try (default
    [8]); the segmentation whose boundaries best follow concave creases is
    kept; [] makes one fewer
contrast_merge_clusters: one more segmentation to choose from in the same
    way: K-means into this many clusters (at least k), merged by contrast
    down to k as the default automatic method does (default 20); 0: not
    tried. extra_clusters=0, alternative_extra_clusters=[] and
    contrast_merge_clusters=0 give the thesis's method
min_candidate_clusters: of the segmentations of extra_clusters and
    alternative_extra_clusters, those of fewer K-means clusters (k + extra)
    are not tried when others are (default 6: with k = 2 or 3, k + 2
    clusters cut the largest body in pieces); 0: all are tried
flat_seam_angle: in the merges, a boundary whose mean concave angle is
    below this many degrees is a flat seam, merged before every other
    boundary, the one between the largest segments first (default 0.5);
    0: off
)doc") + segmentation_method_doc)
          .c_str());

  m.def("k_way_segmentation_automatic",
        [](const py::object& vertices, const py::object& faces, long long max_k, const py::object& min_boundary_contrast,
           const std::string& metric, const std::vector<double>& weights, const std::string& normalization,
           double vsi_fraction, long long max_measured_faces, const py::object& ray_caster, const std::string& kernel,
           const std::string& sampling,
           long long samples, long long seed, bool boundary_enhancement, long long threads,
           const py::object& progress, bool report, bool connect_touching_parts, double contact_distance,
           double speck_area_fraction) {
          const SpectralSeg::Automatic_segmentation_options<> unused; // the salient-cut keywords at their defaults
          return automatic(vertices, faces, "concave-merge", max_k, min_boundary_contrast,
                           unused.segmentability.threshold, unused.segmentability.structure_only, py::none(),
                           py::none(), py::none(), py::none(), metric, weights, normalization, vsi_fraction,
                           max_measured_faces,
                           ray_caster, kernel, sampling, samples, seed, boundary_enhancement, threads, progress, report,
                           connect_touching_parts, contact_distance, speck_area_fraction);
        },
        py::arg("vertices"), py::arg("faces"), py::kw_only(), py::arg("max_k") = default_automatic_max_k,
        py::arg("min_boundary_contrast") = py::none(), py::arg("metric") = "part-aware",
        py::arg("weights") = default_weights, py::arg("normalization") = "p99", py::arg("vsi_fraction") = 0.01,
        py::arg("max_measured_faces") = default_max_measured_faces(),
        py::arg("ray_caster") = py::none(), py::arg("kernel") = "exponential", py::arg("sampling") = "auto",
        py::arg("samples") = 0, py::arg("seed") = 0, py::arg("boundary_enhancement") = true, py::arg("threads") = 0,
        py::arg("progress") = py::none(), py::arg("report") = false,
        py::arg("connect_touching_parts") = true, py::arg("contact_distance") = 0.005,
        py::arg("speck_area_fraction") = 0.01,
        (std::string(R"doc(k_way_segmentation_automatic(vertices, faces, **options) -> labels

Segments the mesh into a number of parts it chooses itself, between 2 and
max_k: over-segments into max_k clusters and merges while the weakest
boundary is weakly concave (SpectralSeg::segment_k_way_automatic();
automatic_segmentation(method='concave_merge') is the same).

max_k: the largest number of segments, default 20 (clamped to faces - 1)
min_boundary_contrast: merging stops once the weakest boundary's mean concave
    angle reaches this many times the mesh's mean concave angle (default 3)
)doc") + segmentation_method_doc)
          .c_str());

  m.def("automatic_segmentation", &automatic, py::arg("vertices"), py::arg("faces"), py::kw_only(),
        py::arg("method") = "contrast_merge", py::arg("max_k") = default_automatic_max_k,
        py::arg("min_boundary_contrast") = py::none(),
        py::arg("eta") = automatic_defaults.segmentability.threshold,
        py::arg("structure_only") = automatic_defaults.segmentability.structure_only,
        py::arg("min_part_area") = py::none(), py::arg("max_parts") = py::none(), py::arg("parts") = py::none(),
        py::arg("depth") = py::none(), py::arg("metric") = "part-aware", py::arg("weights") = default_weights,
        py::arg("normalization") = "p99", py::arg("vsi_fraction") = 0.01,
        py::arg("max_measured_faces") = default_max_measured_faces(), py::arg("ray_caster") = py::none(),
        py::arg("kernel") = "exponential", py::arg("sampling") = "auto", py::arg("samples") = 0,
        py::arg("seed") = 0, py::arg("boundary_enhancement") = true, py::arg("threads") = 0,
        py::arg("progress") = py::none(), py::arg("report") = false,
        py::arg("connect_touching_parts") = true, py::arg("contact_distance") = 0.005,
        py::arg("speck_area_fraction") = 0.01,
        (std::string(R"doc(automatic_segmentation(vertices, faces, **options) -> labels

Segments the mesh into as many parts as it finds (`spectralseg segment --k
auto`), by one of three methods:
    'contrast_merge' (default): over-segment into max_k clusters, merge while
        the weakest boundary is not both concave and a jump of the part-aware
        metric (SpectralSeg::segment_hybrid())
    'concave_merge': the same, judged by concavity alone
        (SpectralSeg::segment_k_way_automatic())
    'salient_cuts': top-down after the thesis's chapter 6, recursive cuts of
        the pieces that pass the segmentability test
        (SpectralSeg::segment_automatically()), with our salience and test;
        the metric, kernel and sampling keywords are refused
    'salient_cuts_thesis': the same as the thesis published it

max_k: clusters of the over-segmentation (merge methods), default 20
min_boundary_contrast: merge methods, default 4 (contrast) or 3 (concave)
eta: salient cuts, segmentability threshold, default 0.1
structure_only: salient cuts, only the L-projection tests, default False
min_part_area: salient cuts, no part under this fraction of its component's
    area, default 0.02 (0 with salient_cuts_thesis)
max_parts: salient cuts, no cut once there are this many parts, default 64
    (no limit, 0, with salient_cuts_thesis)
parts: this many parts, the method's hierarchy cut there instead of where
    the method stops (salient cuts: the first cuts; merge methods: the last
    merges undone, or more merges)
depth: salient cuts, stop every branch of the hierarchy at this depth
With report=True, the report holds the hierarchy ('hierarchy': 'kind' cuts
or merges, 'chosen_cuts', 'leaves', 'roots').
)doc") + segmentation_method_doc)
          .c_str());

  m.def("face_distances", &face_distances, py::arg("vertices"), py::arg("faces"), py::arg("sources"),
        py::kw_only(), py::arg("metric") = "part-aware", py::arg("weights") = default_weights,
        py::arg("normalization") = "p99", py::arg("vsi_fraction") = 0.01,
        py::arg("max_measured_faces") = default_max_measured_faces(), py::arg("ray_caster") = py::none(),
        py::arg("threads") = 0, py::arg("progress") = py::none(), py::arg("return_nearest") = false,
        py::arg("connect_touching_parts") = true, py::arg("contact_distance") = 0.005,
        py::arg("speck_area_fraction") = 0.01,
        R"doc(face_distances(vertices, faces, sources, **options) -> distances

Shortest-path distance, on the dual graph weighted by the metric, from the
nearest of `sources` (a face index or a sequence of them, rows of `faces`)
to every face (SpectralSeg::Weighted_dual_graph::distances(),
`spectralseg distance`). One float64 per row of `faces`: inf for a face no
source reaches, nan for a dropped face. With return_nearest=True, returns
(distances, nearest) where nearest is the position in `sources` of each
face's nearest source (-1 if none).

Keyword arguments: metric, weights, normalization, vsi_fraction, max_measured_faces, ray_caster,
threads, progress, connect_touching_parts, contact_distance and
speck_area_fraction, as for k_way_segmentation().)doc");

  m.def("shape_descriptor", &shape_descriptor, py::arg("vertices"), py::arg("faces"), py::kw_only(),
        py::arg("metric") = "part-aware", py::arg("weights") = std::vector<double>{0.02, 0., 0.98},
        py::arg("normalization") = "p99", py::arg("vsi_fraction") = 0.01,
        py::arg("max_measured_faces") = default_max_measured_faces(), py::arg("ray_caster") = py::none(),
        py::arg("bins") = 64, py::arg("sources") = 32, py::arg("range") = 4.0, py::arg("threads") = 0,
        py::arg("progress") = py::none(), py::arg("connect_touching_parts") = true,
        py::arg("contact_distance") = 0.005, py::arg("speck_area_fraction") = 0.01,
        R"doc(shape_descriptor(vertices, faces, **options) -> dict

Shape descriptor for retrieval (SpectralSeg::shape_descriptor(),
`spectralseg descriptor`): the distribution of the distances between faces
under `metric` ('part-aware', 'geodesic', or 'euclidean' for D2), each face
weighted by its area, distances divided by their mean. Returns a dict with
'metric', 'histogram' (float64, adds up to 1), 'range' (in mean distances),
'mean_distance' and 'sources'.

Keyword arguments: weights (the part-aware coefficients, by default the
thesis's for retrieval 0.02, 0, 0.98), normalization, vsi_fraction and
ray_caster (part-aware only), bins, sources (farthest-point source faces),
range, threads, progress, connect_touching_parts, contact_distance,
speck_area_fraction.)doc");
  m.def("chi_square_distance", &chi_square_distance, py::arg("a"), py::arg("b"),
        R"doc(chi_square_distance(a, b) -> float

Chi-square distance between two descriptors of shape_descriptor(): 0 for
equal histograms, at most 1, symmetric. Raises spectralseg.Error for
descriptors of different metrics or bins.)doc");
  m.def("rank_shapes", &rank_shapes, py::arg("query"), py::arg("database"),
        R"doc(rank_shapes(query, database) -> [(index, distance), ...]

The descriptors of `database` ranked by chi-square distance to `query`,
nearest first; equal distances keep the database order.)doc");
}
