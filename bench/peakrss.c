/*
 * peakrss: run a program and report its peak resident set size.
 *
 *   peakrss OUTFILE PROGRAM [ARGS...]
 *
 * Forks, execs PROGRAM, waits with wait4() and writes the child's ru_maxrss
 * [kB], its elapsed wall time and its CPU time (user + system) to OUTFILE
 * ("maxrss_kb=... elapsed=... cpu=...");
 * exits with the child's exit code. SIGTERM or SIGINT to peakrss kills the
 * child (SIGKILL), so that a timeout in the driver stops the measured run. The benchmark driver starts every
 * measured program through this small process: a program forked directly
 * from the Python driver inherits the driver's (numpy, netCDF) RSS high-water
 * mark across exec, so its own ru_maxrss would read ~40 MB too high.
 */
#define _POSIX_C_SOURCE 200809L
#define _DEFAULT_SOURCE
#include <errno.h>
#include <stdio.h>
#include <string.h>
#include <stdlib.h>
#include <sys/resource.h>
#include <sys/time.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <signal.h>
#include <time.h>
#include <unistd.h>

static volatile pid_t child = 0;

static void forward(int sig)
{
    (void)sig;
    if (child > 0) kill(child, SIGKILL);
}

int main(int argc, char **argv)
{
    if (argc < 3) {
        fprintf(stderr, "usage: peakrss OUTFILE PROGRAM [ARGS...]\n");
        return 2;
    }
    struct timespec t0, t1;
    clock_gettime(CLOCK_MONOTONIC, &t0);
    pid_t pid = fork();
    if (pid < 0) {
        perror("peakrss: fork");
        return 127;
    }
    if (pid == 0) {
        execv(argv[2], argv + 2);
        perror("peakrss: exec");
        _exit(127);
    }
    child = pid;
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = forward;
    sigaction(SIGTERM, &sa, NULL);
    sigaction(SIGINT, &sa, NULL);
    int status = 0;
    struct rusage ru;
    pid_t w;
    while ((w = wait4(pid, &status, 0, &ru)) < 0 && errno == EINTR) {
    }
    if (w < 0) {
        perror("peakrss: wait4");
        return 127;
    }
    clock_gettime(CLOCK_MONOTONIC, &t1);
    FILE *f = fopen(argv[1], "w");
    if (f) {
        fprintf(f, "maxrss_kb=%ld\nelapsed=%.9e\ncpu=%.9e\n", ru.ru_maxrss,
                (double)(t1.tv_sec - t0.tv_sec) + 1e-9 * (double)(t1.tv_nsec - t0.tv_nsec),
                (double)(ru.ru_utime.tv_sec + ru.ru_stime.tv_sec)
                    + 1e-6 * (double)(ru.ru_utime.tv_usec + ru.ru_stime.tv_usec));
        fclose(f);
    }
    if (WIFEXITED(status)) return WEXITSTATUS(status);
    return 128 + (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
}
