// A library with a thread_local of its own, opened by
// test_sanitizer_runtime: glibc mallocs each thread's block of it at that
// thread's first access, as it does log4cplus's in cube4.
namespace {
thread_local void* probe_word = nullptr;
}

// The calling thread's block (allocated at its first call).
extern "C" void* cube4_dtls_probe_block() { return &probe_word; }
