// A measurement tool, not part of the build: read strategies for a large cold file
// (docs/bench/read-strategies-h200/result.txt). Build: g++ -O2 -std=c++20 -static -pthread.
// Read strategies for a large file from a cold page cache.
#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <thread>
#include <vector>

static double now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}
static void drop() {
  sync();
  FILE* f = fopen("/proc/sys/vm/drop_caches", "w");
  if (f) {
    fputs("3", f);
    fclose(f);
  }
}
int main(int argc, char** argv) {
  const char* path = argv[1];
  std::string mode = argv[2];
  if (mode == "write") {
    size_t total = size_t(atoll(argv[3]));
    std::vector<unsigned long> buf(1 << 20);
    unsigned long x = 88172645463325252ul;
    FILE* f = fopen(path, "wb");
    for (size_t done = 0; done < total; done += buf.size() * 8) {
      for (auto& v : buf) {
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        v = x;
      }
      fwrite(buf.data(), 8, std::min(buf.size(), (total - done) / 8), f);
    }
    fflush(f);
    fsync(fileno(f));
    fclose(f);
    return 0;
  }
  int threads = atoi(argv[3]);
  size_t block = size_t(atoi(argv[4])) << 20;
  bool cold = argc > 5 && std::string(argv[5]) == "cold";
  const size_t offset = 4099;  // an unaligned array start, as in a .vti
  struct stat st;
  stat(path, &st);
  size_t bytes = size_t(st.st_size) - offset;
  char* dst = static_cast<char*>(
      mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0));
  madvise(dst, bytes, MADV_HUGEPAGE);
  if (cold) drop();
  double t0 = now();
  bool direct = mode == "direct";
  int fd = open(path, O_RDONLY | (direct ? O_DIRECT : 0));
  if (fd < 0) {
    perror("open");
    return 1;
  }
  if (mode == "seq") posix_fadvise(fd, 0, 0, POSIX_FADV_SEQUENTIAL);
  std::atomic<size_t> next{0};
  std::atomic<bool> failed{false};
  auto work = [&] {
    char* bounce = nullptr;
    if (direct) bounce = static_cast<char*>(aligned_alloc(4096, block + 8192));
    for (;;) {
      size_t b = next.fetch_add(1);
      size_t begin = b * block;
      if (begin >= bytes) break;
      size_t end = std::min(bytes, begin + block);
      if (!direct) {
        size_t at = begin;
        while (at < end) {
          ssize_t n = pread(fd, dst + at, end - at, off_t(offset + at));
          if (n <= 0) {
            failed = true;
            return;
          }
          at += size_t(n);
        }
      } else {
        size_t fileBegin = offset + begin, fileEnd = offset + end;
        size_t alignedBegin = fileBegin & ~size_t(4095);
        size_t alignedEnd = (fileEnd + 4095) & ~size_t(4095);
        size_t want = alignedEnd - alignedBegin, got = 0;
        while (got < want) {
          ssize_t n = pread(fd, bounce + got, want - got, off_t(alignedBegin + got));
          if (n < 0) {
            perror("pread direct");
            failed = true;
            return;
          }
          if (n == 0) break;
          got += size_t(n);
        }
        std::memcpy(dst + begin, bounce + (fileBegin - alignedBegin), end - begin);
      }
    }
    free(bounce);
  };
  std::vector<std::thread> pool;
  for (int i = 0; i < threads; ++i)
    pool.emplace_back(work);
  for (auto& t : pool)
    t.join();
  double t1 = now();
  unsigned long sum = 0;
  for (size_t i = 0; i < bytes; i += 4096)
    sum += (unsigned char)dst[i];
  printf("%s threads %d block %zu MiB %s: %.3f s (%.2f GB/s)%s sum %lu\n", mode.c_str(), threads,
         block >> 20, cold ? "cold" : "warm", t1 - t0, bytes / (t1 - t0) / 1e9,
         failed ? " FAILED" : "", sum);
  return 0;
}
