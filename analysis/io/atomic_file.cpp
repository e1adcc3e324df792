// granpen analysis: checked atomic writes (see atomic_file.h).
#include "atomic_file.h"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <unistd.h>

namespace granpen {

namespace fs = std::filesystem;

namespace {

[[noreturn]] void fail(const std::string &path, const std::string &why)
{
  throw OutputError("cannot write " + path + ": " + why);
}

std::string errno_text() { return std::strerror(errno); }

// ".NAME.tmpPID" beside path: the same folder, so the rename never crosses a file system
std::string temporary_name(const std::string &path)
{
  const fs::path p(path);
  return (p.parent_path() / ("." + p.filename().string() + ".tmp" + std::to_string((long) getpid()))).string();
}

// text into a new file tmp, on disk when this returns; throws naming path
void write_temporary(const std::string &tmp, const std::string &path, const std::string &text)
{
  if (fs::path(path).filename().empty()) fail(path, "not a file name");
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) fail(path, errno_text());
  std::size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const std::string why = errno_text();
      ::close(fd);
      ::unlink(tmp.c_str());
      fail(path, why);
    }
    done += (std::size_t) n;
  }
  // fsync before the rename: the new name never points at data not yet on disk
  if (::fsync(fd) != 0 && errno != EINVAL) {
    const std::string why = errno_text();
    ::close(fd);
    ::unlink(tmp.c_str());
    fail(path, why);
  }
  if (::close(fd) != 0) {
    const std::string why = errno_text();
    ::unlink(tmp.c_str());
    fail(path, why);
  }
}

}    // namespace

void write_file_atomic(const std::string &path, const std::string &text)
{
  write_files_atomic({{path, text}});
}

void write_files_atomic(const std::vector<std::pair<std::string, std::string>> &files)
{
  std::vector<std::string> tmps;
  try {
    for (const auto &f : files) {
      tmps.push_back(temporary_name(f.first));
      write_temporary(tmps.back(), f.first, f.second);
    }
  } catch (...) {
    for (const auto &t : tmps) ::unlink(t.c_str());
    throw;
  }
  for (std::size_t k = 0; k < files.size(); ++k)
    if (std::rename(tmps[k].c_str(), files[k].first.c_str()) != 0) {
      const std::string why = errno_text();
      for (std::size_t j = k; j < tmps.size(); ++j) ::unlink(tmps[j].c_str());
      fail(files[k].first, why);
    }
}

void make_output_dir(const std::string &dir)
{
  std::error_code ec;
  if (fs::is_directory(dir, ec)) return;
  fs::create_directories(dir, ec);
  if (ec) throw OutputError("cannot create " + dir + ": " + ec.message());
}

bool same_file(const std::string &a, const std::string &b)
{
  std::error_code ea, eb;
  const bool xa = fs::exists(a, ea), xb = fs::exists(b, eb);
  if (xa && xb) {
    std::error_code ec;
    return fs::equivalent(a, b, ec) && !ec;
  }
  if (xa || xb) return false;
  std::error_code ec;
  const fs::path pa = fs::absolute(a, ec).lexically_normal(), pb = fs::absolute(b, ec).lexically_normal();
  return pa == pb;
}

void refuse_overwriting_inputs(const std::string &output, const std::string &option,
                               const std::vector<std::string> &inputs)
{
  for (const auto &in : inputs)
    if (same_file(output, in))
      throw OutputError(option + " " + output + " is the input " + in + ": refusing to overwrite it");
}

void refuse_shared_outputs(const std::vector<std::pair<std::string, std::string>> &outputs)
{
  for (std::size_t i = 0; i < outputs.size(); ++i)
    for (std::size_t j = i + 1; j < outputs.size(); ++j)
      if (!outputs[i].second.empty() && !outputs[j].second.empty() && same_file(outputs[i].second, outputs[j].second))
        throw OutputError(outputs[i].first + " " + outputs[i].second + " and " + outputs[j].first + " " +
                          outputs[j].second + " are the same file: one output would replace the other; give each its own name");
}

}    // namespace granpen
