// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// spectralseg batch: the summary table (one row per mesh), written as CSV and
// as JSON lines, and read back to merge the shards of a batch.
#ifndef SPECTRALSEG_TOOLS_BATCH_SUMMARY_H
#define SPECTRALSEG_TOOLS_BATCH_SUMMARY_H

#include <SpectralSeg/exceptions.h>
#include <SpectralSeg/IO/Atomic_output_file.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstddef>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace spectralseg_cli {

// One mesh of the summary. Output paths are relative to the output folder
// (empty: not written).
struct Batch_row
{
  std::string mesh;   // the name: path relative to the batch's root
  std::string status; // "ok" or "error"
  long long faces = -1;    // -1: unknown (error)
  long long segments = -1; // -1: unknown (error)
  double seconds = 0.;     // of the computation, also for a mesh skipped now
  bool skipped = false;    // finished by an earlier run, not computed again
  std::string error;
  std::vector<std::string> warnings; // the reader's repairs
  std::string input;
  std::string labels, json, colored_mesh, png;
};

// The columns, in order; `seconds` is the only one that changes from run to run.
inline const std::vector<std::string>& batch_columns()
{
  static const std::vector<std::string> columns{"mesh",  "status",   "faces", "segments", "seconds",      "skipped", "error",
                                                "warnings", "input", "labels", "json", "colored_mesh", "png"};
  return columns;
}

inline nlohmann::ordered_json to_json(const Batch_row& r)
{
  nlohmann::ordered_json j;
  j["mesh"] = r.mesh;
  j["status"] = r.status;
  j["faces"] = r.faces < 0 ? nlohmann::ordered_json() : nlohmann::ordered_json(r.faces);
  j["segments"] = r.segments < 0 ? nlohmann::ordered_json() : nlohmann::ordered_json(r.segments);
  j["seconds"] = r.seconds;
  j["skipped"] = r.skipped;
  j["error"] = r.error;
  j["warnings"] = r.warnings;
  j["input"] = r.input;
  j["labels"] = r.labels;
  j["json"] = r.json;
  j["colored_mesh"] = r.colored_mesh;
  j["png"] = r.png;
  return j;
}

// \throws nlohmann::json::exception on a malformed row
inline Batch_row row_from_json(const nlohmann::json& j)
{
  Batch_row r;
  r.mesh = j.at("mesh").get<std::string>();
  r.status = j.at("status").get<std::string>();
  r.faces = j.at("faces").is_null() ? -1 : j.at("faces").get<long long>();
  r.segments = j.at("segments").is_null() ? -1 : j.at("segments").get<long long>();
  r.seconds = j.at("seconds").get<double>();
  r.skipped = j.at("skipped").get<bool>();
  r.error = j.at("error").get<std::string>();
  r.warnings = j.at("warnings").get<std::vector<std::string>>();
  r.input = j.at("input").get<std::string>();
  r.labels = j.at("labels").get<std::string>();
  r.json = j.at("json").get<std::string>();
  r.colored_mesh = j.at("colored_mesh").get<std::string>();
  r.png = j.at("png").get<std::string>();
  return r;
}

// A CSV field (RFC 4180): quoted when it holds a comma, a quote or a line break.
inline std::string csv_field(const std::string& text)
{
  if(text.find_first_of(",\"\r\n") == std::string::npos)
    return text;
  std::string out = "\"";
  for(char c : text)
  {
    if(c == '"')
      out += '"';
    out += c;
  }
  return out + "\"";
}

inline std::string seconds_text(double s)
{
  std::ostringstream out;
  out.precision(3);
  out << std::fixed << s;
  return out.str();
}

inline std::string csv_line(const Batch_row& r)
{
  std::string warnings;
  for(const std::string& w : r.warnings)
    warnings += (warnings.empty() ? "" : "; ") + w;
  const std::vector<std::string> fields{r.mesh,
                                        r.status,
                                        r.faces < 0 ? "" : std::to_string(r.faces),
                                        r.segments < 0 ? "" : std::to_string(r.segments),
                                        seconds_text(r.seconds),
                                        r.skipped ? "true" : "false",
                                        r.error,
                                        warnings,
                                        r.input,
                                        r.labels,
                                        r.json,
                                        r.colored_mesh,
                                        r.png};
  std::string line;
  for(std::size_t i = 0; i < fields.size(); ++i)
    line += (i == 0 ? "" : ",") + csv_field(fields[i]);
  return line + "\n";
}

inline void sort_rows(std::vector<Batch_row>& rows)
{
  std::sort(rows.begin(), rows.end(), [](const Batch_row& a, const Batch_row& b) { return a.mesh < b.mesh; });
}

// Writes `stem`.csv and `stem`.jsonl (each all or nothing), rows sorted by mesh.
inline void write_summary(const std::string& stem, std::vector<Batch_row> rows)
{
  sort_rows(rows);
  std::string csv, jsonl;
  for(std::size_t i = 0; i < batch_columns().size(); ++i)
    csv += (i == 0 ? "" : ",") + batch_columns()[i];
  csv += "\n";
  for(const Batch_row& r : rows)
  {
    csv += csv_line(r);
    jsonl += to_json(r).dump() + "\n";
  }
  SpectralSeg::IO::write_text_file(stem + ".csv", csv);
  SpectralSeg::IO::write_text_file(stem + ".jsonl", jsonl);
}

// \throws SpectralSeg::Invalid_input if the file cannot be read or a row is malformed
inline std::vector<Batch_row> read_summary_jsonl(const std::string& path)
{
  std::ifstream in(path);
  if(!in)
    throw SpectralSeg::Io_error("cannot open '" + path + "'");
  std::vector<Batch_row> rows;
  std::string line;
  std::size_t number = 0;
  while(std::getline(in, line))
  {
    ++number;
    if(line.empty())
      continue;
    try
    {
      rows.push_back(row_from_json(nlohmann::json::parse(line)));
    }
    catch(const nlohmann::json::exception& e)
    {
      throw SpectralSeg::Invalid_input("'" + path + "' line " + std::to_string(number) + ": not a summary row (" +
                                       e.what() + ")");
    }
  }
  return rows;
}

} // namespace spectralseg_cli

#endif
