// granpen analysis: an output written piece by piece, then renamed (see staged_file.h).
#include "staged_file.h"

#include "atomic_file.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <unistd.h>

namespace granpen {

namespace {

// writes are gathered into pieces of this size: few system calls, bounded memory
constexpr std::size_t PIECE = 1 << 16;

[[noreturn]] void fail(const std::string &path, const std::string &why)
{
  throw OutputError("cannot write " + path + ": " + why);
}

}    // namespace

StagedFile::StagedFile(const std::string &path) : path_(path)
{
  const std::filesystem::path p(path);
  if (p.filename().empty()) fail(path, "not a file name");
  tmp_ = (p.parent_path() / ("." + p.filename().string() + ".tmp" + std::to_string((long) getpid()))).string();
  fd_ = ::open(tmp_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd_ < 0) fail(path, std::strerror(errno));
}

StagedFile::~StagedFile() { abandon(); }

void StagedFile::abandon()
{
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
  if (!renamed_ && !tmp_.empty()) ::unlink(tmp_.c_str());
  tmp_.clear();
}

void StagedFile::flush()
{
  std::size_t done = 0;
  while (done < buffer_.size()) {
    const ssize_t n = ::write(fd_, buffer_.data() + done, buffer_.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) fail(path_, std::strerror(errno));
    done += (std::size_t) n;
  }
  buffer_.clear();
}

void StagedFile::write(const std::string &text)
{
  if (fd_ < 0) fail(path_, "already closed");
  buffer_ += text;
  if (buffer_.size() >= PIECE) flush();
}

void StagedFile::close()
{
  if (fd_ < 0) fail(path_, "already closed");
  flush();
  // fsync before the rename: the new name never points at data not yet on disk
  if (::fsync(fd_) != 0 && errno != EINVAL) fail(path_, std::strerror(errno));
  const int fd = fd_;
  fd_ = -1;
  if (::close(fd) != 0) fail(path_, std::strerror(errno));
}

void StagedFile::rename()
{
  if (fd_ >= 0) close();
  if (std::rename(tmp_.c_str(), path_.c_str()) != 0) fail(path_, std::strerror(errno));
  renamed_ = true;
}

}    // namespace granpen
