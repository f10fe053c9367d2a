// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// spectralseg batch: the list of meshes (files, folders, list files), their
// stable output names, the shards, and the content hashes that tell a
// finished output from a stale one.
#ifndef SPECTRALSEG_TOOLS_BATCH_INPUTS_H
#define SPECTRALSEG_TOOLS_BATCH_INPUTS_H

#include "Argument_checks.h"

#include <SpectralSeg/exceptions.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <set>
#include <string>
#include <system_error>
#include <vector>

#include <sys/stat.h>

namespace spectralseg_cli {

namespace fs = std::filesystem;

// One mesh of a batch.
struct Batch_mesh
{
  std::string input; // the path it is read from: as given, or the folder given joined with its place in it
  std::string name;  // its path relative to the root, '/'-separated: the key of the summary and of its outputs
};

// The meshes of a batch, sorted by name (the same on every machine).
struct Batch_list
{
  std::vector<Batch_mesh> meshes;
  std::string root; // the absolute folder the names are relative to
};

// 64-bit FNV-1a, as 16 hexadecimal digits: the hashes of the options, the
// mesh list and the files. Not cryptographic: it tells changed from unchanged.
class Fnv1a
{
public:
  void add(const char* data, std::size_t n)
  {
    for(std::size_t i = 0; i < n; ++i)
    {
      h_ ^= static_cast<unsigned char>(data[i]);
      h_ *= 0x100000001b3ull;
    }
  }
  void add(const std::string& s) { add(s.data(), s.size()); }
  std::string hex() const
  {
    char text[17];
    std::snprintf(text, sizeof(text), "%016llx", static_cast<unsigned long long>(h_));
    return text;
  }

private:
  std::uint64_t h_ = 0xcbf29ce484222325ull;
};

inline std::string hash_text(const std::string& text)
{
  Fnv1a h;
  h.add(text);
  return h.hex();
}

// \throws SpectralSeg::Io_error if the file cannot be read
inline std::string hash_file(const std::string& path)
{
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if(f == nullptr)
    throw SpectralSeg::Io_error("cannot read '" + path + "': " + std::strerror(errno));
  Fnv1a h;
  std::vector<char> buffer(1 << 20);
  std::size_t n = 0;
  while((n = std::fread(buffer.data(), 1, buffer.size(), f)) > 0)
    h.add(buffer.data(), n);
  const bool failed = std::ferror(f) != 0;
  std::fclose(f);
  if(failed)
    throw SpectralSeg::Io_error("cannot read '" + path + "'");
  return h.hex();
}

// Size and modification time of a file (through symbolic links).
struct File_stamp
{
  bool exists = false;
  long long size = -1;
  long long mtime_ns = -1;

  bool operator==(const File_stamp& o) const { return exists == o.exists && size == o.size && mtime_ns == o.mtime_ns; }
  bool operator!=(const File_stamp& o) const { return !(*this == o); }
};

inline File_stamp stamp_of(const std::string& path)
{
  File_stamp s;
  struct stat st;
  if(::stat(path.c_str(), &st) != 0)
    return s;
  s.exists = true;
  s.size = static_cast<long long>(st.st_size);
  s.mtime_ns = static_cast<long long>(st.st_mtim.tv_sec) * 1000000000ll + static_cast<long long>(st.st_mtim.tv_nsec);
  return s;
}

inline bool has_mesh_extension(const fs::path& p)
{
  std::string ext = p.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext == ".off" || ext == ".obj" || ext == ".ply" || ext == ".stl";
}

// An absolute path without "." or ".." components nor a trailing slash;
// symbolic links are kept (a mesh is named by the path it was given by).
inline fs::path absolute_normal(const fs::path& p)
{
  fs::path a = fs::absolute(p).lexically_normal();
  if(!a.has_filename() && a.has_parent_path() && a != a.root_path())
    a = a.parent_path();
  return a;
}

// The deepest folder holding every path of `folders` (absolute, normal).
inline fs::path common_folder(const std::vector<fs::path>& folders)
{
  if(folders.empty())
    return absolute_normal(fs::current_path());
  std::vector<fs::path> common(folders.front().begin(), folders.front().end());
  for(const fs::path& f : folders)
  {
    std::size_t i = 0;
    for(auto it = f.begin(); it != f.end() && i < common.size() && *it == common[i]; ++it)
      ++i;
    common.resize(i);
  }
  fs::path out;
  for(const fs::path& part : common)
    out /= part;
  return out;
}

// The lines of a list file ('-': standard input), trimmed; empty lines and
// lines starting with '#' are skipped.
inline std::vector<std::string> read_list_file(const std::string& path)
{
  std::ifstream file;
  if(path != "-")
  {
    file.open(path);
    if(!file)
      throw SpectralSeg::Io_error("cannot open the list '" + path + "': " + std::strerror(errno));
  }
  std::istream& in = path == "-" ? std::cin : file;
  std::vector<std::string> out;
  std::string line;
  while(std::getline(in, line))
  {
    const std::size_t first = line.find_first_not_of(" \t\r");
    if(first == std::string::npos || line[first] == '#')
      continue;
    const std::size_t last = line.find_last_not_of(" \t\r");
    out.push_back(line.substr(first, last - first + 1));
  }
  if(in.bad())
    throw SpectralSeg::Io_error("cannot read the list '" + path + "'");
  return out;
}

// The names of the files a batch writes for itself in its output folder
// (summary-shard-I-of-N.csv... for a shard): no mesh may be named so that
// one of its outputs takes one of these names.
inline bool is_reserved_batch_name(const std::string& mesh_name)
{
  return mesh_name == "batch" || mesh_name.rfind("batch-shard-", 0) == 0;
}

// Collects the meshes: each file argument and list entry, and the mesh files
// (.off, .obj, .ply, .stl, any case) of each folder argument (with their
// subfolders if `recursive`; hidden files and folders, symbolic links to
// folders met on the way, and the output folder are skipped). A path given
// twice counts once. Names are the paths relative to `root` (default: the
// deepest folder holding every folder argument and the folder of every file).
// \throws SpectralSeg::Io_error if an argument or list does not exist or a folder cannot be read
// \throws Usage_error if a mesh is outside `root` or the output folder is an input folder
inline Batch_list list_batch_meshes(const std::vector<std::string>& inputs, const std::vector<std::string>& lists,
                                    bool recursive, const std::string& root, const std::string& out)
{
  const fs::path out_abs = absolute_normal(out);
  std::vector<std::pair<std::string, fs::path>> found; // input as given, absolute path
  std::vector<fs::path> anchors;
  auto add_file = [&](const std::string& input) {
    const fs::path a = absolute_normal(input);
    found.emplace_back(input, a);
    anchors.push_back(a.parent_path());
  };
  for(const std::string& input : inputs)
  {
    std::error_code ec;
    const fs::file_status st = fs::status(input, ec);
    if(!fs::exists(st))
      throw SpectralSeg::Io_error("cannot open '" + input + "': no such file or folder");
    if(!fs::is_directory(st))
    {
      add_file(input);
      continue;
    }
    const fs::path folder = absolute_normal(input);
    if(folder == out_abs)
      throw Usage_error("the output folder '" + out + "' is also an input folder: give another --out");
    anchors.push_back(folder);
    auto visit = [&](const fs::directory_entry& e, auto& iterator) {
      const std::string leaf = e.path().filename().string();
      std::error_code ignored;
      if(!leaf.empty() && leaf[0] == '.')
      {
        if constexpr(std::is_same_v<std::decay_t<decltype(iterator)>, fs::recursive_directory_iterator>)
          if(e.is_directory(ignored))
            iterator.disable_recursion_pending();
        return;
      }
      if(e.is_directory(ignored))
      {
        if constexpr(std::is_same_v<std::decay_t<decltype(iterator)>, fs::recursive_directory_iterator>)
          if(absolute_normal(e.path()) == out_abs)
            iterator.disable_recursion_pending();
        return;
      }
      if(e.is_regular_file(ignored) && has_mesh_extension(e.path()))
        add_file((fs::path(input) / e.path().lexically_relative(folder)).generic_string());
    };
    auto fail = [&](const std::error_code& error) {
      throw SpectralSeg::Io_error("cannot read the folder '" + input + "': " + error.message());
    };
    // the same walk over either kind of iterator
    auto walk = [&](auto it) {
      const decltype(it) end;
      if(ec)
        fail(ec);
      for(; it != end; it.increment(ec))
      {
        if(ec)
          fail(ec);
        visit(*it, it);
      }
      if(ec)
        fail(ec);
    };
    if(recursive)
      walk(fs::recursive_directory_iterator(folder, ec));
    else
      walk(fs::directory_iterator(folder, ec));
  }
  for(const std::string& list : lists)
    for(const std::string& entry : read_list_file(list))
      add_file(entry);

  Batch_list result;
  const fs::path root_abs = root.empty() ? common_folder(anchors) : absolute_normal(root);
  result.root = root_abs.string();
  std::set<fs::path> seen;
  for(const auto& f : found)
  {
    if(!seen.insert(f.second).second)
      continue;
    const fs::path relative = f.second.lexically_relative(root_abs);
    const std::string name = relative.generic_string();
    if(name.empty() || name == "." || *relative.begin() == "..")
      throw Usage_error("'" + f.first + "' is not inside the --root folder '" + root + "'");
    if(is_reserved_batch_name(name))
      throw Usage_error("'" + f.first + "': a mesh named '" + name +
                        "' would take the name of the batch's own files in the output folder; rename it");
    result.meshes.push_back({f.first, name});
  }
  std::sort(result.meshes.begin(), result.meshes.end(),
            [](const Batch_mesh& a, const Batch_mesh& b) { return a.name < b.name; });
  return result;
}

// --shard I/N
struct Shard
{
  std::size_t index = 0;
  std::size_t count = 1;
  bool given = false;

  bool takes(std::size_t position) const { return position % count == index; }
  std::string suffix() const
  {
    return given ? "-shard-" + std::to_string(index) + "-of-" + std::to_string(count) : std::string();
  }
};

// \throws Usage_error unless `text` is I/N with 0 <= I < N
inline Shard parse_shard(const std::string& text)
{
  Shard s;
  if(text.empty())
    return s;
  const std::size_t slash = text.find('/');
  auto number = [&](const std::string& part, std::size_t& v) {
    if(part.empty() || part.size() > 9 || part.find_first_not_of("0123456789") != std::string::npos)
      return false;
    v = std::stoul(part);
    return true;
  };
  if(slash == std::string::npos || !number(text.substr(0, slash), s.index) || !number(text.substr(slash + 1), s.count) ||
     s.count == 0 || s.index >= s.count)
    throw Usage_error("--shard must be I/N with 0 <= I < N, counting from 0 (got '" + text + "')");
  s.given = true;
  return s;
}

} // namespace spectralseg_cli

#endif
