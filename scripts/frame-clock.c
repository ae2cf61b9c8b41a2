// LD_PRELOAD shim for scripts/bench-frame.sh: records the clocks at every glfwSwapBuffers of a
// program (the editor links GLFW dynamically), so any build of the editor, old or new, can be timed
// frame by frame without a hook of its own. At exit it writes one line per frame to $FRAME_CLOCK_OUT:
// process CPU ms, main-thread CPU ms, wall ms, each the difference to the previous swap, and the
// frame's end in Unix seconds (to drop the frames before a scripted press).
#define _GNU_SOURCE
#include <dlfcn.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

typedef struct GLFWwindow GLFWwindow;

enum { kMaxFrames = 100000 };
static double processMs[kMaxFrames], threadMs[kMaxFrames], wallMs[kMaxFrames], unixMs[kMaxFrames];
static int frames;

static double clockMs(clockid_t clock) {
    struct timespec t;
    clock_gettime(clock, &t);
    return (double)t.tv_sec * 1e3 + (double)t.tv_nsec * 1e-6;
}

void glfwSwapBuffers(GLFWwindow* window) {
    static void (*real)(GLFWwindow*);
    if (!real) *(void**)&real = dlsym(RTLD_NEXT, "glfwSwapBuffers");
    real(window);
    if (frames >= kMaxFrames) return;
    // The swap runs on the main thread: its thread clock is the UI thread's, the process clock adds
    // the worker threads (background jobs, the GL driver's).
    processMs[frames] = clockMs(CLOCK_PROCESS_CPUTIME_ID);
    threadMs[frames] = clockMs(CLOCK_THREAD_CPUTIME_ID);
    wallMs[frames] = clockMs(CLOCK_MONOTONIC);
    unixMs[frames] = clockMs(CLOCK_REALTIME);
    ++frames;
}

__attribute__((destructor)) static void writeFrames(void) {
    const char* path = getenv("FRAME_CLOCK_OUT");
    if (!path || frames == 0) return; // xvfb-run and xdotool carry the preload too: they swap nothing
    FILE* out = fopen(path, "w");
    if (!out) {
        fprintf(stderr, "frame-clock: cannot write %s\n", path);
        return;
    }
    fprintf(out, "process_cpu_ms thread_cpu_ms wall_ms end_unix_s\n");
    for (int k = 1; k < frames; ++k)
        fprintf(out, "%.4f %.4f %.4f %.4f\n", processMs[k] - processMs[k - 1], threadMs[k] - threadMs[k - 1],
                wallMs[k] - wallMs[k - 1], unixMs[k] * 1e-3);
    fclose(out);
}
