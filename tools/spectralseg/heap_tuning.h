// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// How the tool uses glibc's heap: freed memory kept, the page size chosen by
// timing both, and pages faulted in ahead on two cores while a mesh is read.
#ifndef SPECTRALSEG_TOOLS_HEAP_TUNING_H
#define SPECTRALSEG_TOOLS_HEAP_TUNING_H

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cctype>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <system_error>
#include <thread>
#include <utility>

#if defined(__GLIBC__)
#include <malloc.h>
#endif
#if defined(__linux__)
#include <sys/mman.h>
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

// The largest block prepare_heap() takes: below the mmap threshold of
// keep_freed_memory_in_heap(), so that the block comes from the heap and
// stays in it once freed.
constexpr std::size_t max_prefault_bytes = std::size_t(768) << 20;

// The page size of a stretch of the heap.
enum class Page_size
{
  none, // not chosen: the kernel's policy
  small, // 4 KB
  huge   // 2 MB
};

// The size of a huge page (x86-64), the unit of madvise() below.
constexpr std::size_t huge_page_bytes = std::size_t(2) << 20;

// The whole huge pages inside [block, block + bytes): their first byte and
// their length (0 when there is none).
inline std::pair<char*, std::size_t> whole_huge_pages(char* block, std::size_t bytes)
{
  const std::uintptr_t begin = reinterpret_cast<std::uintptr_t>(block);
  const std::uintptr_t first = (begin + huge_page_bytes - 1) / huge_page_bytes * huge_page_bytes;
  const std::uintptr_t last = (begin + bytes) / huge_page_bytes * huge_page_bytes;
  return {reinterpret_cast<char*>(first), last > first ? std::size_t(last - first) : 0};
}

// Advises the whole huge pages inside [block, block + bytes) for the page
// size `size` (none: nothing); whether the kernel took the advice.
inline bool advise_page_size(char* block, std::size_t bytes, Page_size size)
{
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  const std::pair<char*, std::size_t> pages = whole_huge_pages(block, bytes);
  return size != Page_size::none && pages.second > 0 &&
         madvise(pages.first, pages.second, size == Page_size::huge ? MADV_HUGEPAGE : MADV_NOHUGEPAGE) == 0;
#else
  (void)block;
  (void)bytes;
  (void)size;
  return false;
#endif
}

// Chooses the page size of the whole huge pages inside [block, block +
// bytes) by timing both there: the first 2 MB in 4 KB pages (512 page
// faults), the next two in huge pages (one fault each); the rest then in
// huge pages when the faster of the two took less time than the 512 small
// pages, else in 4 KB pages. Returns the choice; none, with nothing
// changed, where fewer than four whole huge pages lie inside or the kernel
// has no transparent huge pages. Only timing depends on it.
//
// Which is cheaper depends on the machine, and on a virtual machine on its
// host's state (doc/benchmarks.md): on bare metal a 4 KB fault costs about
// a microsecond and zeroing 2 MB about 100; on this project's virtual
// machine a 4 KB fault has cost 2 to 12 us, and a huge page 0.1 ms where
// the host had backed the memory before and up to 20 ms where it backed it
// 4 KB after 4 KB.
inline Page_size choose_page_size(char* block, std::size_t bytes)
{
  constexpr std::size_t huge = huge_page_bytes, page = 4096;
  const std::pair<char*, std::size_t> pages = whole_huge_pages(block, bytes);
  char* const start = pages.first;
  if(pages.second < 4 * huge || !advise_page_size(start, huge, Page_size::small) ||
     !advise_page_size(start + huge, pages.second - huge, Page_size::huge))
    return Page_size::none;
  typedef std::chrono::steady_clock Clock;
  const auto touch = [&](std::size_t from, std::size_t to) {
    const Clock::time_point begin = Clock::now();
    for(std::size_t i = from; i < to; i += page)
      static_cast<volatile char*>(start)[i] = 0;
    return Clock::now() - begin;
  };
  const Clock::duration small = touch(0, huge);
  const Clock::duration large = std::min(touch(huge, huge + page), touch(2 * huge, 2 * huge + page));
  if(large < small)
    return Page_size::huge;
  advise_page_size(start + 3 * huge, pages.second - 3 * huge, Page_size::small);
  return Page_size::small;
}

// Whether the environment variable GLIBC_TUNABLES (`tunables`, may be null)
// sets glibc.malloc.hugetlb, glibc's own choice of page size for its heaps:
// the tool then leaves the page size to it.
inline bool page_size_set_by_glibc_tunable(const char* tunables)
{
  return tunables != nullptr && std::string(tunables).find("glibc.malloc.hugetlb=") != std::string::npos;
}

// What prepare_heap() does to the heap before a mesh file is read.
struct Heap_preparation
{
  // bytes at the top of the heap whose page size choose_page_size() chooses
  // (it touches the first 6 MB of them)
  std::size_t page_choice_bytes = 0;
  // bytes, among those, faulted in on two threads
  std::size_t prefault_bytes = 0;
};

// Chooses the page size of the first `plan.page_choice_bytes` bytes of fresh
// heap memory (choose_page_size() the first time in a process, the same
// choice after) and faults in the first
// `plan.prefault_bytes` of them on two threads (each at most
// max_prefault_bytes), then frees them. With
// keep_freed_memory_in_heap(), the freed block joins the free memory at
// the top of the heap, and the allocations that follow are carved from it
// in the order they would have been: only timing changes, nothing is read
// from the block.
//
// Every page a command touches for the first time costs a page fault, dear
// on virtual machines (about 10 us a 4 KB page on the reference host, where
// a 2 MB page has cost what a dozen 4 KB pages do; doc/benchmarks.md).
// Linux gives huge pages only to memory advised so
// (`madvise(MADV_HUGEPAGE)`) when transparent huge pages are set to
// "madvise", as on Ubuntu and on the reference host, and to all memory with
// "always"; "never" overrides the advice. Pages advised but never touched
// stay free.
//
// Reading a mesh runs on one core for most of its time, faulting in its
// arrays one page after the other: the prefaulted part is touched on two
// threads first. The other thread is started before the block is
// allocated, so that nothing is allocated after it.
inline void prepare_heap(const Heap_preparation& plan)
{
  constexpr std::size_t page = 4096;
  const std::size_t prefault = std::min(plan.prefault_bytes, max_prefault_bytes) / 2 / page * 2 * page;
  const std::size_t bytes = std::max(std::min(plan.page_choice_bytes, max_prefault_bytes), prefault);
  if(bytes < 2 * page)
    return;
  const std::size_t half = prefault / 2;
  const auto touch = [](char* block, std::size_t from, std::size_t to) {
    for(std::size_t i = from; i < to; i += page)
      static_cast<volatile char*>(block)[i] = 0;
  };
  std::atomic<char*> shared(nullptr);
  std::atomic<bool> given(false);
  std::thread other;
  if(half > 0)
  {
    try
    {
      other = std::thread([&] {
        while(!given.load())
          std::this_thread::yield();
        if(char* block = shared.load())
          touch(block, half, prefault);
      });
    }
    catch(const std::system_error&)
    {
      // no thread to spare: the pages fault in where they are used
    }
  }
  char* block = static_cast<char*>(std::malloc(bytes));
  if(block != nullptr && plan.page_choice_bytes > 0)
  {
    // chosen once per process: a later block (the next mesh of a batch) may
    // lie in memory already mapped, where timing tells nothing
    static std::atomic<Page_size> chosen(Page_size::none);
    const std::size_t length = std::min(bytes, plan.page_choice_bytes);
    if(chosen.load() == Page_size::none)
      chosen = choose_page_size(block, length);
    else
      advise_page_size(block, length, chosen.load());
  }
  shared = block;
  given = true;
  if(other.joinable())
  {
    if(block != nullptr)
      touch(block, 0, half);
    other.join();
  }
  std::free(block);
}

// What to prepare before reading a mesh file of `file_bytes` bytes with
// extension `extension` (lower case, with its dot) on `threads` threads
// (0: all), against the heap a segmentation of it peaks at (about 800 bytes
// a face, 22 to 30 times an OFF file's size; an ASCII OFF file takes 30 to
// 60 bytes a face, an OBJ file up to 80 with texture coordinates and
// normals, an STL file 50 in binary and about 250 in ASCII):
// - the page size chosen for 32 times the size of an OFF or PLY file, 24
//   times an OBJ file's, 8 times an STL file's: about the peak (nothing when
//   `glibc_tunables`, the value of GLIBC_TUNABLES, sets glibc's own
//   choice);
// - faulted in on two threads, when there are two threads and two cores: 12
//   times the size of an OFF or PLY file, 8 times an OBJ file's, 3 times an
//   STL file's, below the peak so that the peak does not grow.
inline Heap_preparation heap_preparation(std::uintmax_t file_bytes, const std::string& extension, unsigned threads,
                                         const char* glibc_tunables = nullptr)
{
  const bool stl = extension == ".stl", obj = extension == ".obj";
  const auto times = [&](std::uintmax_t factor) {
    return std::size_t(std::min<std::uintmax_t>(factor * std::min<std::uintmax_t>(file_bytes, max_prefault_bytes),
                                                max_prefault_bytes));
  };
  Heap_preparation plan;
  if(!page_size_set_by_glibc_tunable(glibc_tunables))
    plan.page_choice_bytes = times(stl ? 8 : obj ? 24 : 32);
  if(threads != 1 && std::thread::hardware_concurrency() >= 2)
    plan.prefault_bytes = times(stl ? 3 : obj ? 8 : 12);
  return plan;
}

// prepare_heap() before reading the mesh file `path` on `threads` threads.
inline void prepare_heap_for_mesh_file(const std::string& path, unsigned threads)
{
  std::error_code error;
  const std::uintmax_t size = std::filesystem::file_size(path, error);
  if(error)
    return; // the reader says why
  std::string extension = std::filesystem::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  prepare_heap(heap_preparation(size, extension, threads, std::getenv("GLIBC_TUNABLES")));
}

} // namespace spectralseg_cli

#endif // SPECTRALSEG_TOOLS_HEAP_TUNING_H
