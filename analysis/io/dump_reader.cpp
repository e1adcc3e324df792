/* ----------------------------------------------------------------------
   granpen analysis: streaming LAMMPS dump reader.

   Files are read through one growing byte buffer (plain files with read(2),
   gzip files with zlib's gzread), cut into lines with memchr and parsed in
   place: no iostreams, no per-value allocation. Numbers take a fast exact
   path (8 digits at a time, Clinger's exact case) and otherwise
   std::from_chars; both give strtod's value bit for bit. The caller's frame
   is filled directly, reusing its vectors' capacity; on any error it is
   emptied before the InputError propagates.
------------------------------------------------------------------------- */

#include "dump_reader.h"
#include "text_util.h"

#include <zlib.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace granpen {

// ---------------------------------------------------------------- DumpFrame

std::size_t DumpFrame::natoms() const
{
  return data.empty() ? 0 : data[0].size();
}

bool DumpFrame::has(const std::string &name) const
{
  return std::find(columns.begin(), columns.end(), name) != columns.end();
}

const std::vector<double> &DumpFrame::col(const std::string &name) const
{
  for (std::size_t c = 0; c < columns.size() && c < data.size(); ++c)
    if (columns[c] == name) return data[c];
  throw InputError(file + ":" + std::to_string(line) + ": frame has no column " + name);
}

// ---------------------------------------------------------------- helpers

namespace {

using Clock = std::chrono::steady_clock;

constexpr std::size_t kInitialBuffer = std::size_t(1) << 22;    // 4 MiB
constexpr std::size_t kSlack = 16;    // readable bytes kept after the buffer's data (digit_run)
constexpr std::size_t kMaxLine = std::size_t(1) << 30;          // a line longer than 1 GiB is not a dump
constexpr std::size_t kReserveCap = std::size_t(1) << 23;       // values reserved ahead per frame, at most

inline bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

// printable, shortened copy of a token or line for error messages
std::string show(const char *b, const char *e, std::size_t max = 60)
{
  std::string s;
  for (const char *p = b; p < e && s.size() < max; ++p) {
    unsigned char c = static_cast<unsigned char>(*p);
    if (c >= 32 && c < 127) {
      s += static_cast<char>(c);
    } else {
      static const char hex[] = "0123456789abcdef";
      s += "\\x";
      s += hex[c >> 4];
      s += hex[c & 15];
    }
  }
  if (static_cast<std::size_t>(e - b) > max) s += "...";
  return s;
}

inline const char *skip_space(const char *p, const char *e)
{
  while (p < e && is_space(*p)) ++p;
  return p;
}

inline const char *token_end(const char *p, const char *e)
{
  while (p < e && !is_space(*p)) ++p;
  return p;
}

std::vector<std::string> tokens(const char *b, const char *e)
{
  std::vector<std::string> out;
  for (const char *p = skip_space(b, e); p < e; p = skip_space(p, e)) {
    const char *q = token_end(p, e);
    out.emplace_back(p, q);
    p = q;
  }
  return out;
}

inline const char *trim_end(const char *b, const char *e)
{
  while (e > b && is_space(e[-1])) --e;
  return e;
}

// the line (trailing white space ignored) is exactly `what`
inline bool line_is(const char *b, const char *e, const char *what)
{
  e = trim_end(b, e);
  std::size_t n = std::strlen(what);
  return static_cast<std::size_t>(e - b) == n && std::memcmp(b, what, n) == 0;
}

inline bool line_starts(const char *b, const char *e, const char *what)
{
  std::size_t n = std::strlen(what);
  return static_cast<std::size_t>(e - b) >= n && std::memcmp(b, what, n) == 0;
}

enum class NumStatus { ok, bad, nonfinite };

// Exact powers of ten of a double
constexpr double kPow10[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8,  1e9,  1e10, 1e11,
                             1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};

inline bool is_digit(char c) { return static_cast<unsigned>(c - '0') < 10u; }

// Powers of ten as integers, for joining integer and fraction digits
constexpr std::uint64_t kPow10i[] = {1, 10, 100, 1000, 10000, 100000, 1000000, 10000000, 100000000};

// Length (0..8) of the run of decimal digits at s, at most e - s, and their value.
// Reads 8 bytes at s: the buffer keeps kSlack readable bytes after its data.
__attribute__((always_inline)) inline int digit_run(const char *s, const char *e, std::uint64_t &value)
{
  std::uint64_t x;
  std::memcpy(&x, s, 8);
  const std::uint64_t t = x ^ 0x3030303030303030ull;    // digits become 0..9, everything else >= 10
  const std::uint64_t nondigit = ((t + 0x7676767676767676ull) | t) & 0x8080808080808080ull;
  int n = nondigit ? __builtin_ctzll(nondigit) >> 3 : 8;
  if (n > e - s) n = static_cast<int>(e - s);
  if (n == 0) {
    value = 0;
    return 0;
  }
  std::uint64_t v = t << (8 * (8 - n));    // the n digits in the top bytes, zeros before them
  v = v * 10 + (v >> 8);
  v = (((v & 0x000000FF000000FFull) * 0x000F424000000064ull) +
       (((v >> 16) & 0x000000FF000000FFull) * 0x0000271000000001ull)) >> 32;
  value = v;
  return n;
}

// The end of a number both fast paths share: the digits m scaled by 10^k, an optional
// exponent at s, then a separator; exact only while m <= 2^53 and |k| <= 22
__attribute__((always_inline)) inline bool finish_simple(const char *s, const char *e, bool neg, std::uint64_t m, int k, double &v, const char *&q)
{
  if (s < e && (*s == 'e' || *s == 'E')) {
    ++s;
    bool eneg = false;
    if (s < e && (*s == '-' || *s == '+')) {
      eneg = *s == '-';
      ++s;
    }
    if (s == e || !is_digit(*s)) return false;
    int x = 0;
    for (; s < e && is_digit(*s); ++s)
      if (x < 100000) x = x * 10 + (*s - '0');
    k += eneg ? -x : x;
  }
  if (s < e && !is_space(*s)) return false;
  if (m == 0) {
    v = neg ? -0.0 : 0.0;
  } else {
    if (m > (std::uint64_t(1) << 53) || k < -22 || k > 22) return false;
    const double d = static_cast<double>(static_cast<std::int64_t>(m));    // m <= 2^53: signed is exact, and cheaper
    v = k < 0 ? d / kPow10[-k] : d * kPow10[k];
    if (neg) v = -v;
  }
  q = s;
  return true;
}

// The common case, decimals whose value is m * 10^k with m <= 2^53 and
// |k| <= 22 (every %g field LAMMPS writes): one exactly rounded multiplication
// or division (Clinger's fast path), so the result is the correctly rounded
// value, bit for bit what strtod returns. false: not such a number, or one
// this path leaves to from_chars. Digits are taken 8 at a time (digit_run);

// longer runs go the scalar way.
inline bool parse_simple_scalar(const char *p, const char *e, double &v, const char *&q);

__attribute__((always_inline)) inline bool parse_simple(const char *p, const char *e, double &v, const char *&q)
{
  const char *s = p;
  const bool neg = *s == '-';
  s += (*s == '-' || *s == '+');
  std::uint64_t m, f;
  const int n1 = digit_run(s, e, m);
  if (n1 == 8) return parse_simple_scalar(p, e, v, q);
  s += n1;
  int n2 = 0;
  if (s < e && *s == '.') {
    ++s;
    n2 = digit_run(s, e, f);
    if (n2 == 8) return parse_simple_scalar(p, e, v, q);
    m = m * kPow10i[n2] + f;
    s += n2;
  }
  if (n1 + n2 == 0) return false;
  int k = -n2;
  return finish_simple(s, e, neg, m, k, v, q);
}

// the same, one digit at a time: up to 19 significant digits
inline bool parse_simple_scalar(const char *p, const char *e, double &v, const char *&q)
{
  const char *s = p;
  bool neg = false;
  if (*s == '-' || *s == '+') {
    neg = *s == '-';
    ++s;
  }
  std::uint64_t m = 0;
  int ndig = 0, k = 0;
  bool any = false;
  for (; s < e && is_digit(*s); ++s) {
    any = true;
    if (m || *s != '0') {
      if (++ndig > 19) return false;
      m = m * 10 + static_cast<unsigned>(*s - '0');
    }
  }
  if (s < e && *s == '.') {
    for (++s; s < e && is_digit(*s); ++s) {
      any = true;
      --k;
      if (m || *s != '0') {
        if (++ndig > 19) return false;
        m = m * 10 + static_cast<unsigned>(*s - '0');
      }
    }
  }
  if (!any) return false;
  return finish_simple(s, e, neg, m, k, v, q);
}

inline NumStatus parse_double(const char *p, const char *e, double &v, const char *&q)
{
  if (parse_simple(p, e, v, q)) return NumStatus::ok;
  const char *s = p;
  if (*s == '+' && s + 1 < e && *(s + 1) != '-' && *(s + 1) != '+') ++s;    // from_chars takes no '+'
  auto r = std::from_chars(s, e, v);
  q = r.ptr;
  if (r.ec == std::errc::result_out_of_range) {
    // overflow is an error; underflow (subnormal or zero) is a fine value
    std::string tok(p, token_end(p, e));
    char *end = nullptr;
    v = std::strtod(tok.c_str(), &end);
    q = p + (end - tok.c_str());
    if (!std::isfinite(v)) return NumStatus::nonfinite;
  } else if (r.ec != std::errc()) {
    q = p;
    return NumStatus::bad;
  }
  if (q < e && !is_space(*q)) return NumStatus::bad;
  if (!std::isfinite(v)) return NumStatus::nonfinite;
  return NumStatus::ok;
}

// the line holds exactly one integer
bool parse_integer_line(const char *b, const char *e, long long &v)
{
  const char *p = skip_space(b, e);
  e = trim_end(p, e);
  if (p == e) return false;
  if (*p == '+' && p + 1 < e && *(p + 1) != '-') ++p;
  auto r = std::from_chars(p, e, v);
  return r.ec == std::errc() && r.ptr == e;
}

// ---------------------------------------------------------------- sources

struct Source {
  virtual ~Source() = default;
  // up to n bytes into dst; 0 at the end. Throws std::runtime_error with zlib's/errno's words.
  virtual std::size_t read(char *dst, std::size_t n) = 0;
  virtual std::uint64_t consumed() const = 0;    // bytes of the stored file taken so far
  virtual void close() = 0;                      // throws if the stream turns out bad
};

struct PlainSource : Source {
  int fd;
  std::uint64_t got = 0;
  explicit PlainSource(int f) : fd(f) {}
  ~PlainSource() override
  {
    if (fd >= 0) ::close(fd);
  }
  std::size_t read(char *dst, std::size_t n) override
  {
    for (;;) {
      ssize_t r = ::read(fd, dst, n);
      if (r >= 0) {
        got += static_cast<std::uint64_t>(r);
        return static_cast<std::size_t>(r);
      }
      if (errno != EINTR) throw std::runtime_error(std::string("read error: ") + std::strerror(errno));
    }
  }
  std::uint64_t consumed() const override { return got; }
  void close() override
  {
    if (fd >= 0) ::close(fd);
    fd = -1;
  }
};

struct GzipSource : Source {
  gzFile gz;
  std::uint64_t last_offset = 0;
  bool truncated = false;
  explicit GzipSource(gzFile g) : gz(g) {}
  ~GzipSource() override
  {
    if (gz) gzclose_r(gz);
  }
  std::string zerror()
  {
    int err = Z_OK;
    const char *msg = gzerror(gz, &err);
    std::string m = msg && *msg ? std::string(msg) : std::string("error ") + std::to_string(err);
    if (m.compare(0, 4, "<fd:") == 0 && m.find(": ") != std::string::npos) m = m.substr(m.find(": ") + 2);
    return m;    // without zlib's "<fd:N>: " prefix
  }
  std::size_t read(char *dst, std::size_t n) override
  {
    if (truncated) throw std::runtime_error("gzip stream truncated (zlib: unexpected end of file)");
    const unsigned chunk = static_cast<unsigned>(std::min<std::size_t>(n, 1u << 30));
    int r = gzread(gz, dst, chunk);
    if (r < 0) throw std::runtime_error("corrupt gzip stream (zlib: " + zerror() + ")");
    int err = Z_OK;
    gzerror(gz, &err);
    if (err == Z_BUF_ERROR) {
      // cut short: hand out what was decompressed, fail on the next read
      truncated = true;
      if (r == 0) throw std::runtime_error("gzip stream truncated (zlib: unexpected end of file)");
    } else if (err != Z_OK) {
      throw std::runtime_error("corrupt gzip stream (zlib: " + zerror() + ")");
    }
    z_off_t off = gzoffset(gz);
    if (off >= 0) last_offset = static_cast<std::uint64_t>(off);
    return static_cast<std::size_t>(r);
  }
  std::uint64_t consumed() const override { return last_offset; }
  void close() override
  {
    if (!gz) return;
    int r = gzclose_r(gz);
    gz = nullptr;
    if (r == Z_BUF_ERROR) throw std::runtime_error("gzip stream truncated (zlib: unexpected end of file)");
    if (r != Z_OK) throw std::runtime_error("gzip stream could not be closed cleanly (zlib error " + std::to_string(r) + ")");
  }
};

}    // namespace

// ---------------------------------------------------------------- the reader

struct DumpReader::Impl {
  std::vector<std::string> paths;
  std::vector<std::string> required;
  std::size_t next_file = 0;    // index of the next file to open
  std::string path;             // the file being read
  std::unique_ptr<Source> src;
  std::uint64_t file_size = 0;
  std::uint64_t bytes_done = 0;    // stored bytes of finished files
  long frames_in_file = 0;

  std::vector<char> buf;
  std::size_t pos = 0, end = 0;    // unread bytes are buf[pos, end)
  bool eof = false;                // the source is exhausted
  long lineno = 0;                 // number of the line last returned

  std::uint64_t frames = 0;
  bool finished = false;
  std::string error;    // sticky: once thrown, thrown again

  Clock::time_point t0 = Clock::now();
  std::function<void(const DumpProgress &)> cb;
  double every = 2.0;
  Clock::time_point last_cb = Clock::now();

  [[noreturn]] void fail(long line, const std::string &what)
  {
    error = path + ":" + std::to_string(line) + ": " + what;
    throw InputError(error);
  }

  DumpProgress progress() const
  {
    DumpProgress p;
    p.frames = frames;
    p.bytes = bytes_done;
    if (src) {
      std::uint64_t c = src->consumed();
      // for a plain file, what was parsed rather than what sits in the buffer
      if (dynamic_cast<PlainSource *>(src.get())) c -= std::min<std::uint64_t>(c, end - pos);
      p.bytes += c;
    }
    p.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
    return p;
  }

  void maybe_report(bool force)
  {
    if (!cb) return;
    auto now = Clock::now();
    if (force || std::chrono::duration<double>(now - last_cb).count() >= every) {
      last_cb = now;
      cb(progress());
    }
  }

  void open(const std::string &p)
  {
    path = p;
    lineno = 0;
    frames_in_file = 0;
    pos = end = 0;
    eof = false;
    try {
      require_regular_file(p);    // a FIFO would block the open
    } catch (const InputError &e) {
      error = e.what();
      throw;
    }
    int fd = ::open(p.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) {
      error = p + ": cannot open dump file (" + std::strerror(errno) + ")";
      throw InputError(error);
    }
    struct stat st;
    file_size = (fstat(fd, &st) == 0 && S_ISREG(st.st_mode)) ? static_cast<std::uint64_t>(st.st_size) : 0;
    unsigned char magic[4] = {0, 0, 0, 0};
    ssize_t n = 0;
    while (n < 4) {
      ssize_t r = ::pread(fd, magic + n, 4 - n, n);
      if (r < 0 && errno == EINTR) continue;
      if (r <= 0) break;
      n += r;
    }
    const char *other = nullptr;    // compressions LAMMPS or users may use that this reader does not read
    if (n == 4 && magic[0] == 0x28 && magic[1] == 0xb5 && magic[2] == 0x2f && magic[3] == 0xfd) other = "zstd";
    if (n == 4 && magic[0] == 0xfd && magic[1] == '7' && magic[2] == 'z' && magic[3] == 'X') other = "xz";
    if (n >= 3 && magic[0] == 'B' && magic[1] == 'Z' && magic[2] == 'h') other = "bzip2";
    if (other) {
      ::close(fd);
      error = p + ":1: " + other + "-compressed file: only plain text and gzip dumps are read (decompress it first)";
      throw InputError(error);
    }
    if (n >= 2 && magic[0] == 0x1f && magic[1] == 0x8b) {
      gzFile gz = gzdopen(fd, "rb");
      if (!gz) {
        ::close(fd);
        error = p + ": cannot open gzip stream";
        throw InputError(error);
      }
      gzbuffer(gz, 1u << 20);
      src.reset(new GzipSource(gz));
    } else {
      posix_fadvise(fd, 0, 0, POSIX_FADV_SEQUENTIAL);
      src.reset(new PlainSource(fd));
    }
    // 4 MiB reads, less for a small file (a gzip file's text may be much larger than it)
    const std::uint64_t want = file_size ? std::min<std::uint64_t>(kInitialBuffer, std::max<std::uint64_t>(
                                                                         std::uint64_t(1) << 16, 16 * file_size))
                                         : kInitialBuffer;
    if (buf.size() < want + kSlack) buf.assign(want + kSlack, '\0');
  }

  // close the current file; throws if a gzip stream turns out to be cut short
  void close_file()
  {
    try {
      src->close();
    } catch (std::runtime_error &e) {
      fail(lineno, e.what());
    }
    std::uint64_t c = src->consumed();
    bytes_done += std::max(c, file_size);
    src.reset();
  }

  // read more bytes, keeping buf[pos, end); false when the source is exhausted
  bool refill()
  {
    if (eof) return false;
    if (pos > 0) {
      std::memmove(buf.data(), buf.data() + pos, end - pos);
      end -= pos;
      pos = 0;
    }
    if (end == buf.size() - kSlack) {
      if (buf.size() >= kMaxLine) fail(lineno + 1, "line longer than " + std::to_string(kMaxLine) + " bytes");
      buf.resize((buf.size() - kSlack) * 2 + kSlack);
    }
    std::size_t n = 0;
    try {
      n = src->read(buf.data() + end, buf.size() - kSlack - end);
    } catch (std::runtime_error &e) {
      fail(lineno, e.what());
    }
    end += n;
    if (n == 0) eof = true;
    maybe_report(false);
    return n > 0;
  }

  // next line, without its '\n'; false at the end of the file
  bool getline(const char *&b, const char *&e)
  {
    for (;;) {
      const char *base = buf.data();
      const void *nl = std::memchr(base + pos, '\n', end - pos);
      if (nl) {
        b = base + pos;
        e = static_cast<const char *>(nl);
        pos = static_cast<std::size_t>(e - base) + 1;
        ++lineno;
        return true;
      }
      if (!refill()) {
        if (pos == end) return false;
        b = buf.data() + pos;    // a last line without '\n'
        e = buf.data() + end;
        pos = end;
        ++lineno;
        return true;
      }
    }
  }

  bool next_nonblank(const char *&b, const char *&e)
  {
    while (getline(b, e))
      if (skip_space(b, e) != e) return true;
    return false;
  }

  // frame: the one being read, for messages
  long frame_line = 0;
  long long frame_step = 0;

  [[noreturn]] void eof_in_frame(const std::string &expect)
  {
    fail(lineno, "file ends inside the frame of timestep " + std::to_string(frame_step) +
                     " (ITEM: TIMESTEP at line " + std::to_string(frame_line) + "): expected " + expect);
  }

  void item_line(const char *&b, const char *&e, const char *item)
  {
    if (!getline(b, e)) eof_in_frame(std::string("'ITEM: ") + item + "'");
    if (!line_starts(b, e, "ITEM: ") || !line_starts(b + 6, e, item))
      fail(lineno, std::string("expected 'ITEM: ") + item + "', found '" + show(b, e) + "'");
  }

  // the error on atom line b..e (atom i of n), field c at p
  [[noreturn]] __attribute__((noinline, cold)) void bad_atom_line(const DumpFrame &f, const char *b, const char *e,
                                                                   const char *p, std::size_t i, std::size_t n,
                                                                   std::size_t c, NumStatus s)
  {
    if (c == 0 && line_starts(b, e, "ITEM:"))
      fail(lineno, "frame truncated: '" + show(b, e) + "' after " + std::to_string(i) + " of " + std::to_string(n) +
                       " atom lines (frame of timestep " + std::to_string(frame_step) + ", ITEM: TIMESTEP at line " +
                       std::to_string(frame_line) + ")");
    if (p == e)
      fail(lineno, "atom line has " + std::to_string(c) + " fields, expected " + std::to_string(f.columns.size()));
    fail(lineno, "column " + f.columns[c] + " value '" + show(p, token_end(p, e)) + "' is " +
                     (s == NumStatus::nonfinite ? "not finite" : "not a number"));
  }

  // the optional ITEM: UNITS and ITEM: TIME (dump_modify units/time yes), then
  // 'ITEM: TIMESTEP'; false at the end of the current file
  bool read_frame_start()
  {
    const char *b, *e;
    if (!next_nonblank(b, e)) return false;
    if (line_is(b, e, "ITEM: UNITS")) {
      long l = lineno;
      if (!getline(b, e)) fail(l, "file ends after 'ITEM: UNITS'");
      if (!getline(b, e)) fail(lineno, "file ends after the units line");
    }
    if (line_is(b, e, "ITEM: TIME")) {
      long l = lineno;
      if (!getline(b, e)) fail(l, "file ends after 'ITEM: TIME'");
      double t;
      const char *q;
      const char *p = skip_space(b, e);
      if (p == e || parse_double(p, e, t, q) != NumStatus::ok || skip_space(q, e) != e)
        fail(lineno, "ITEM: TIME value '" + show(b, e) + "' is not a finite number");
      if (!getline(b, e)) fail(lineno, "file ends after the time");
    }
    if (!line_is(b, e, "ITEM: TIMESTEP")) {
      std::string hint;
      if (frames_in_file > 0 && !line_starts(b, e, "ITEM:"))
        hint = " (more atom lines than NUMBER OF ATOMS in the previous frame?)";
      else if (frames_in_file == 0 && lineno == 1)
        hint = " (not a LAMMPS text dump?)";
      fail(lineno, "expected 'ITEM: TIMESTEP', found '" + show(b, e) + "'" + hint);
    }
    return true;
  }

  // the last frame's timestep and where it was, across files: time must not go backwards
  bool have_step = false;
  long long last_step = 0;
  std::string last_step_at;    // FILE:LINE

  // the timestep line; a step below the previous frame's is an error (one equal to it is
  // not: a resumed run's first dump repeats the step its restart was written at)
  void read_timestep(DumpFrame &f)
  {
    const char *b, *e;
    long long step = 0;
    if (!getline(b, e)) eof_in_frame("the timestep");
    if (!parse_integer_line(b, e, step)) fail(lineno, "timestep '" + show(b, e) + "' is not an integer");
    if (have_step && step < last_step) {
      const bool other_file = last_step_at.compare(0, path.size() + 1, path + ":") != 0;
      fail(lineno, "timestep " + std::to_string(step) + " goes backwards (after timestep " +
                       std::to_string(last_step) + " at " + last_step_at + ")" +
                       (other_file ? ": dump files are read in the order given; give them in time order" : ""));
    }
    have_step = true;
    last_step = step;
    last_step_at = path + ":" + std::to_string(frame_line);
    f.timestep = frame_step = step;
  }

  std::size_t read_natoms()
  {
    const char *b, *e;
    item_line(b, e, "NUMBER OF ATOMS");
    if (!line_is(b, e, "ITEM: NUMBER OF ATOMS"))
      fail(lineno, "malformed ITEM line '" + show(b, e) + "', expected 'ITEM: NUMBER OF ATOMS'");
    long long natoms = 0;
    if (!getline(b, e)) eof_in_frame("the number of atoms");
    if (!parse_integer_line(b, e, natoms) || natoms < 0)
      fail(lineno, "number of atoms '" + show(b, e) + "' is not an integer >= 0");
    return static_cast<std::size_t>(natoms);
  }

  void read_box(DumpFrame &f)
  {
    const char *b, *e;
    item_line(b, e, "BOX BOUNDS");
    if (b + 16 < e && !is_space(b[16]))
      fail(lineno, "malformed ITEM line '" + show(b, e) + "', expected 'ITEM: BOX BOUNDS'");
    for (auto &t : tokens(b + 16, e))
      if (t == "xy" || t == "xz" || t == "yz" || t == "abc" || t == "origin")
        fail(lineno, "triclinic box ('" + show(b, e) + "'): only orthogonal boxes are supported");
    for (int d = 0; d < 3; ++d) {
      if (!getline(b, e)) eof_in_frame("box bounds");
      double v[3];
      int n = 0;
      const char *p = skip_space(b, e);
      while (p < e) {
        if (n == 3) break;
        const char *q;
        NumStatus s = parse_double(p, e, v[n], q);
        if (s != NumStatus::ok)
          fail(lineno, "box bound '" + show(p, token_end(p, e)) + "' is not a finite number");
        ++n;
        p = skip_space(q, e);
      }
      if (n == 3) fail(lineno, "box bounds with a tilt factor: triclinic boxes are not supported");
      if (n != 2) fail(lineno, "box bounds line must hold 'lo hi', found '" + show(b, e) + "'");
      if (v[1] < v[0]) fail(lineno, "box bounds lo > hi ('" + show(b, e) + "')");
      f.lo[d] = v[0];
      f.hi[d] = v[1];
    }
  }

  // the 'ITEM: ATOMS' column names, positions renamed x y z (x beats xu beats xs beats
  // xsu); scaled[d]: the column of a scaled coordinate to convert, or -1
  std::vector<std::string> read_atom_columns(int scaled[3])
  {
    const char *b, *e;
    item_line(b, e, "ATOMS");
    const long atoms_line = lineno;
    auto names = tokens(b + 11, e);
    if (b + 11 < e && !is_space(b[11]))
      fail(lineno, "malformed ITEM line '" + show(b, e) + "', expected 'ITEM: ATOMS NAME...'");
    if (names.empty()) fail(lineno, "'ITEM: ATOMS' names no columns");
    for (std::size_t i = 0; i < names.size(); ++i)
      for (std::size_t j = 0; j < i; ++j)
        if (names[i] == names[j]) fail(lineno, "column '" + names[i] + "' appears twice in 'ITEM: ATOMS'");

    auto find = [&](const std::string &n) -> int {
      for (std::size_t i = 0; i < names.size(); ++i)
        if (names[i] == n) return static_cast<int>(i);
      return -1;
    };
    static const char *axis[3] = {"x", "y", "z"};
    for (int d = 0; d < 3; ++d) {
      scaled[d] = -1;
      const std::string a = axis[d];
      if (find(a) >= 0) continue;
      int i = find(a + "u");
      if (i >= 0) {
        names[i] = a;
        continue;
      }
      i = find(a + "s");
      if (i < 0) i = find(a + "su");
      if (i >= 0) {
        names[i] = a;
        scaled[d] = i;
      }
    }
    for (auto &r : required)
      if (std::find(names.begin(), names.end(), r) == names.end()) {
        std::string have;
        for (auto &n : names) have += (have.empty() ? "" : " ") + n;
        fail(atoms_line, "frame has no column " + r + " (required; columns: " + have + ")");
      }
    return names;
  }

  // the n atom lines into f.data: the hot loop
  void read_atom_lines(DumpFrame &f, std::size_t n)
  {
    const std::size_t ncol = f.columns.size();
    f.data.resize(ncol);
    const std::size_t reserve = std::min(n, std::max<std::size_t>(1024, kReserveCap / ncol));
    for (auto &c : f.data) {
      c.clear();
      c.reserve(reserve);    // NUMBER OF ATOMS is not trusted with memory: the vectors grow past this
    }
    const char *b, *e;
    std::vector<double> *cols = f.data.data();
    for (std::size_t i = 0; i < n; ++i) {
      if (!getline(b, e)) {
        fail(lineno, "file ends inside the frame of timestep " + std::to_string(frame_step) +
                         " (ITEM: TIMESTEP at line " + std::to_string(frame_line) + "): " + std::to_string(i) +
                         " of " + std::to_string(n) + " atom lines");
      }
      const char *p = b;
      for (std::size_t c = 0; c < ncol; ++c) {
        p = skip_space(p, e);
        double v;
        const char *q;
        if (__builtin_expect(p == e || !parse_simple(p, e, v, q), 0)) {
          NumStatus s = p == e ? NumStatus::bad : parse_double(p, e, v, q);
          if (s != NumStatus::ok) bad_atom_line(f, b, e, p, i, n, c, s);
        }
        cols[c].push_back(v);
        p = q;
      }
      p = skip_space(p, e);
      if (p != e) {
        std::size_t extra = tokens(p, e).size();
        fail(lineno, "atom line has " + std::to_string(ncol + extra) + " fields, expected " + std::to_string(ncol));
      }
    }
  }

  // reads one frame into f; false at the end of the current file
  bool read_frame(DumpFrame &f)
  {
    if (!read_frame_start()) return false;
    frame_line = lineno;
    frame_step = 0;
    f.file = path;
    f.line = lineno;
    read_timestep(f);
    const std::size_t n = read_natoms();
    read_box(f);
    int scaled[3];
    f.columns = read_atom_columns(scaled);
    read_atom_lines(f, n);
    for (int d = 0; d < 3; ++d) {
      if (scaled[d] < 0) continue;
      const double lo = f.lo[d], L = f.hi[d] - f.lo[d];
      for (double &v : f.data[scaled[d]]) v = lo + v * L;
    }
    ++frames_in_file;
    return true;
  }

  bool next(DumpFrame &f)
  {
    if (!error.empty()) throw InputError(error);
    if (finished) return false;
    for (;;) {
      if (!src) {
        if (next_file >= paths.size()) {
          finished = true;
          maybe_report(true);
          return false;
        }
        open(paths[next_file++]);
      }
      if (read_frame(f)) {
        ++frames;
        maybe_report(false);
        return true;
      }
      if (frames_in_file == 0) fail(std::max(lineno, 1L), "no dump frames in file (empty or blank)");
      close_file();
    }
  }
};

DumpReader::DumpReader(std::vector<std::string> paths, std::vector<std::string> required) : impl_(new Impl)
{
  if (paths.empty()) throw InputError("dump reader: no dump files given");
  impl_->paths = std::move(paths);
  impl_->required = std::move(required);
}

DumpReader::~DumpReader() = default;

bool DumpReader::next(DumpFrame &frame)
{
  try {
    return impl_->next(frame);
  } catch (...) {
    // never leave a partly read frame behind
    frame.columns.clear();
    frame.data.clear();
    frame.timestep = 0;
    frame.line = 0;
    throw;
  }
}

DumpProgress DumpReader::progress() const
{
  return impl_->progress();
}

void DumpReader::on_progress(std::function<void(const DumpProgress &)> cb, double every_seconds)
{
  impl_->cb = std::move(cb);
  impl_->every = every_seconds;
  impl_->last_cb = Clock::now();
}

}    // namespace granpen
