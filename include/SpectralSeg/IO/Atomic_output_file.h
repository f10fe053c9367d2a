// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file Atomic_output_file.h
/// \brief Writing a file all or nothing: into a temporary file beside it,
/// every write checked, renamed into place at the end.
#ifndef SPECTRALSEG_IO_ATOMIC_OUTPUT_FILE_H
#define SPECTRALSEG_IO_ATOMIC_OUTPUT_FILE_H

#include <SpectralSeg/exceptions.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ostream>
#include <streambuf>
#include <string>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace SpectralSeg {
namespace IO {

/// \cond SKIP_IN_MANUAL
namespace internal {

// A stream buffer over a C file that remembers the first write error.
class File_streambuf : public std::streambuf
{
public:
  explicit File_streambuf(std::FILE* file) : file_(file) { setp(buffer_, buffer_ + sizeof(buffer_)); }
  int error() const { return error_; }

protected:
  int_type overflow(int_type c) override
  {
    if(!drain())
      return traits_type::eof();
    if(!traits_type::eq_int_type(c, traits_type::eof()))
    {
      *pptr() = traits_type::to_char_type(c);
      pbump(1);
    }
    return traits_type::not_eof(c);
  }
  int sync() override { return drain() ? 0 : -1; }

private:
  bool drain()
  {
    const std::size_t n = std::size_t(pptr() - pbase());
    if(n > 0 && error_ == 0 && std::fwrite(pbase(), 1, n, file_) != n)
      error_ = errno != 0 ? errno : EIO;
    setp(buffer_, buffer_ + sizeof(buffer_));
    return error_ == 0;
  }

  std::FILE* file_;
  char buffer_[1 << 16];
  int error_ = 0;
};

// The directory part of a path ("." for a bare name).
inline std::string directory_of(const std::string& path)
{
  const std::size_t slash = path.find_last_of('/');
  if(slash == std::string::npos)
    return ".";
  return slash == 0 ? "/" : path.substr(0, slash);
}

// Creates a new, empty file with a unique name beside `target` (mode 0666
// less the umask); returns its descriptor and sets `name`, or -1 and errno.
inline int create_file_beside(const std::string& target, std::string& name)
{
  static std::atomic<unsigned> counter{0};
  const std::string dir = directory_of(target);
  const std::string base = target.substr(target.find_last_of('/') == std::string::npos ? 0 : target.find_last_of('/') + 1);
  for(int attempt = 0; attempt < 100; ++attempt)
  {
    name = dir + "/." + base + ".tmp" + std::to_string(::getpid()) + "_" + std::to_string(counter++);
    const int fd = ::open(name.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if(fd >= 0 || errno != EEXIST)
      return fd;
  }
  return -1;
}

// The file a path finally names, through symbolic links (the path itself
// if it does not exist yet).
inline std::string resolved_path(const std::string& path)
{
  char* real = ::realpath(path.c_str(), nullptr);
  if(real == nullptr)
    return path;
  std::string out(real);
  std::free(real);
  return out;
}

} // namespace internal
/// \endcond

/// \ingroup PkgSpectralSegIO
/// \brief An output file written all or nothing.
///
/// The data goes to a new temporary file in the directory of `path`
/// (named `.NAME.tmpPID_N`); `commit()` flushes it, checks every write,
/// syncs it to disk, closes it and renames it over `path`. Until then, and
/// whenever a write, the flush, the sync, the close or the rename fails
/// (a full disk, a quota, a file-size limit), the file at `path` is left as
/// it was, the temporary file is removed and `Io_error` says why. If `path`
/// exists and is not a regular file (`/dev/null`, `/dev/stdout`, a pipe),
/// it is written directly, with the same checks. A symbolic link is
/// followed: the file it names is replaced, the link kept. An existing
/// file's permissions are kept.
class Atomic_output_file
{
public:
  /// \throws Io_error if the temporary file cannot be created
  explicit Atomic_output_file(const std::string& path) : path_(path)
  {
    const std::string target = internal::resolved_path(path);
    struct stat st;
    const bool exists = ::stat(target.c_str(), &st) == 0;
    if(exists && S_ISDIR(st.st_mode))
      throw Io_error("cannot write '" + path + "': it is a directory");
    if(exists && !S_ISREG(st.st_mode))
    {
      file_ = std::fopen(target.c_str(), "wb");
      if(file_ == nullptr)
        throw Io_error("cannot write '" + path + "': " + std::strerror(errno));
    }
    else
    {
      if(exists && ::access(target.c_str(), W_OK) != 0)
        throw Io_error("cannot write '" + path + "': " + std::strerror(errno));
      target_ = target;
      const int fd = internal::create_file_beside(target, temporary_);
      if(fd < 0)
        throw Io_error("cannot write '" + path + "': cannot create a file in '" + internal::directory_of(target) +
                       "': " + std::strerror(errno));
      if(exists)
        (void)::fchmod(fd, st.st_mode & 07777);
      file_ = ::fdopen(fd, "wb");
      if(file_ == nullptr)
      {
        const int error = errno;
        ::close(fd);
        ::unlink(temporary_.c_str());
        throw Io_error("cannot write '" + path + "': " + std::strerror(error));
      }
    }
    buffer_ = new internal::File_streambuf(file_);
    stream_ = new std::ostream(buffer_);
  }

  Atomic_output_file(const Atomic_output_file&) = delete;
  Atomic_output_file& operator=(const Atomic_output_file&) = delete;

  /// discards the data if `commit()` was not called or failed
  ~Atomic_output_file() { discard(); }

  /// the stream to write to
  std::ostream& stream() { return *stream_; }

  /// the C file to write to (for libraries that take one); mixing it with
  /// `stream()` is allowed if `stream()` is flushed first
  std::FILE* file()
  {
    stream_->flush();
    return file_;
  }

  /// the path given to the constructor
  const std::string& path() const { return path_; }

  /// Writes the data to disk and puts the file in place.
  /// \throws Io_error if any write failed or the file cannot be put in place
  void commit()
  {
    stream_->flush();
    int error = buffer_->error();
    if(error == 0 && (std::fflush(file_) != 0 || std::ferror(file_) != 0))
      error = errno != 0 ? errno : EIO;
    if(error == 0 && !temporary_.empty() && ::fsync(::fileno(file_)) != 0)
      error = errno;
    const int closed = std::fclose(file_);
    file_ = nullptr;
    if(error == 0 && closed != 0)
      error = errno != 0 ? errno : EIO;
    if(error == 0 && !temporary_.empty() && std::rename(temporary_.c_str(), target_.c_str()) != 0)
      error = errno;
    if(error != 0)
    {
      const bool replaced = !temporary_.empty();
      discard();
      throw Io_error("cannot write '" + path_ + "': " + std::strerror(error) +
                     (replaced ? " (the previous file, if any, is left unchanged)" : ""));
    }
    temporary_.clear();
  }

private:
  void discard()
  {
    delete stream_;
    stream_ = nullptr;
    delete buffer_;
    buffer_ = nullptr;
    if(file_ != nullptr)
      std::fclose(file_);
    file_ = nullptr;
    if(!temporary_.empty())
      ::unlink(temporary_.c_str());
    temporary_.clear();
  }

  std::string path_;
  std::string target_;
  std::string temporary_;
  std::FILE* file_ = nullptr;
  internal::File_streambuf* buffer_ = nullptr;
  std::ostream* stream_ = nullptr;
};

/// \ingroup PkgSpectralSegIO
/// \brief Writes `text` to `path` with an `Atomic_output_file`.
/// \throws Io_error if the file cannot be written; the old file is then intact
inline void write_text_file(const std::string& path, const std::string& text)
{
  Atomic_output_file out(path);
  out.stream() << text;
  out.commit();
}

/// \ingroup PkgSpectralSegIO
/// \brief Checks, before a long computation, that `path` can be written:
/// creates and removes a file in its directory (or, if `path` exists and is
/// not a regular file, opens it for writing). Does nothing for an empty path.
/// \throws Io_error naming `path` and the reason if it cannot
inline void check_writable(const std::string& path)
{
  if(path.empty())
    return;
  struct stat st;
  const std::string target = internal::resolved_path(path);
  if(::stat(target.c_str(), &st) == 0 && !S_ISREG(st.st_mode) && !S_ISDIR(st.st_mode))
  {
    // a device or a pipe: opening a pipe would wait for its reader
    if(::access(target.c_str(), W_OK) != 0)
      throw Io_error("cannot write '" + path + "': " + std::strerror(errno));
    return;
  }
  Atomic_output_file probe(path); // its temporary file is removed again without a commit
}

} // namespace IO
} // namespace SpectralSeg

#endif // SPECTRALSEG_IO_ATOMIC_OUTPUT_FILE_H
