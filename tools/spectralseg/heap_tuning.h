// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// How the tool uses glibc's heap: freed memory kept, and pages faulted in
// ahead on two cores while a mesh is read.
#ifndef SPECTRALSEG_TOOLS_HEAP_TUNING_H
#define SPECTRALSEG_TOOLS_HEAP_TUNING_H

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <system_error>
#include <thread>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace spectralseg_cli {

// glibc serves blocks above 128 KB to 32 MB with mmap and gives them back
// on free, and gives the free memory at the top of a heap back above 128
// KB; the next stage then page-faults the same amount in again. A
// segmentation allocates and frees many such arrays (the mesh, the dual
// graph, the rays' hits, the embedding, the max-flow graphs of the graph
// cut), so the tool keeps them in the heap (doc/benchmarks.md): less time,
// a few percent more peak memory. The library leaves malloc alone;
// programs may do the same.
//
// Kept memory stays in the heap of the thread that freed it, and glibc
// gives up to eight heaps per core to the threads: the worker threads of
// the metric, the embedding and the candidates' graph cuts each kept their
// high-water mark (doc/benchmarks.md). One heap for every thread lets a
// thread reuse what another freed: the candidates' graph cuts in a second
// thread reuse the embeddings freed in the first (armadillo 832,000 faces:
// a resident peak 3-13 MB lower than with one heap per core, and less
// dependent on which thread takes which candidate; doc/benchmarks.md).
inline void keep_freed_memory_in_heap()
{
#if defined(__GLIBC__)
  mallopt(M_MMAP_THRESHOLD, 1 << 30);
  mallopt(M_TRIM_THRESHOLD, 1 << 30);
  mallopt(M_ARENA_MAX, 1);
#endif
}

// The largest block prefault_heap() touches: below the mmap threshold of
// keep_freed_memory_in_heap(), so that the block comes from the heap and
// stays in it once freed.
constexpr std::size_t max_prefault_bytes = std::size_t(768) << 20;

// Faults in up to `bytes` (at most max_prefault_bytes) of fresh heap
// memory on two threads, then frees it. Every page a command touches for
// the first time costs a page fault, dear on virtual machines (about 12 us
// a 4 KB page on the reference host, doc/benchmarks.md), and reading a mesh
// runs on one core for most of its time, faulting in its arrays one page
// after the other. With keep_freed_memory_in_heap(), the freed block joins
// the free memory at the top of the heap, and the allocations that follow
// are carved from it in the order they would have been, from pages already
// mapped. The other thread is started first, so that nothing is allocated
// after the block. Only timing changes: nothing is read from the block.
inline void prefault_heap(std::size_t bytes)
{
  constexpr std::size_t page = 4096;
  bytes = std::min(bytes, max_prefault_bytes);
  if(bytes < 2 * page)
    return;
  const std::size_t half = bytes / 2 / page * page;
  const auto touch = [](char* block, std::size_t from, std::size_t to) {
    for(std::size_t i = from; i < to; i += page)
      static_cast<volatile char*>(block)[i] = 0;
  };
  std::atomic<char*> shared(nullptr);
  std::atomic<bool> given(false);
  std::thread other;
  try
  {
    other = std::thread([&] {
      while(!given.load())
        std::this_thread::yield();
      if(char* block = shared.load())
        touch(block, half, bytes);
    });
  }
  catch(const std::system_error&)
  {
    return; // no thread to spare: the pages fault in where they are used
  }
  char* block = static_cast<char*>(std::malloc(bytes));
  shared = block;
  given = true;
  if(block != nullptr)
    touch(block, 0, half);
  other.join();
  std::free(block);
}

// What to prefault before reading a mesh file of `file_bytes` bytes with
// extension `extension` (lower case, with its dot) on `threads` threads
// (0: all): a multiple of the file's size that stays below the heap a
// segmentation of it peaks at (about 800 bytes a face, 22 to 30 times an
// OFF file's size): 12 times the size of an OFF or PLY file (an ASCII OFF
// file takes 30 to 60 bytes a face), 8 times an OBJ file's (up to 80 with
// texture coordinates and normals), 3 times an STL file's (50 in binary,
// about 250 in ASCII). Nothing on one thread or on one core.
inline std::size_t prefault_bytes(std::uintmax_t file_bytes, const std::string& extension, unsigned threads)
{
  if(threads == 1 || std::thread::hardware_concurrency() < 2)
    return 0;
  const std::uintmax_t factor = extension == ".stl" ? 3 : extension == ".obj" ? 8 : 12;
  return std::size_t(std::min<std::uintmax_t>(factor * std::min<std::uintmax_t>(file_bytes, max_prefault_bytes),
                                              max_prefault_bytes));
}

// prefault_heap() before reading the mesh file `path` on `threads` threads.
inline void prefault_heap_for_mesh_file(const std::string& path, unsigned threads)
{
  std::error_code error;
  const std::uintmax_t size = std::filesystem::file_size(path, error);
  if(error)
    return; // the reader says why
  std::string extension = std::filesystem::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  prefault_heap(prefault_bytes(size, extension, threads));
}

} // namespace spectralseg_cli

#endif // SPECTRALSEG_TOOLS_HEAP_TUNING_H
