/*
 * Replay driver of the fuzz target without libFuzzer: runs
 * LLVMFuzzerTestOneInput (fuzz_deck.c) on each file named on the command
 * line, each in a child process with a time limit, and prints one line per
 * file, "PASS fuzz.NAME" or "FAIL fuzz.NAME: why" (counted by
 * scripts/check.sh). A file passes when the child exits normally with
 * status 0: no crash, no abort (the target aborts on an unclean outcome:
 * an internal error, or an input error without file:line), within the
 * time limit.
 *   fuzz_replay [-t SECONDS] [-q] FILE...
 * -q prints the PASS lines as one summary line (for the seed corpus).
 */
#include <errno.h>
#include <signal.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static int replay_one(const char *path)
{
    FILE *f = fopen(path, "rb");
    if (!f) {
        fprintf(stderr, "fuzz_replay: %s: %s\n", path, strerror(errno));
        return 1;
    }
    size_t cap = 1 << 16, n = 0;
    uint8_t *buf = malloc(cap);
    while (buf) {
        n += fread(buf + n, 1, cap - n, f);
        if (n < cap) break;
        uint8_t *p = realloc(buf, cap * 2);
        if (!p) { free(buf); buf = NULL; break; }
        buf = p;
        cap *= 2;
    }
    int bad = !buf || ferror(f);
    fclose(f);
    if (bad) {
        fprintf(stderr, "fuzz_replay: %s: cannot read it\n", path);
        free(buf);
        return 1;
    }
    LLVMFuzzerTestOneInput(buf, n);
    free(buf);
    return 0;
}

int main(int argc, char **argv)
{
    int limit = 20, quiet = 0, first = 1, npass = 0, nfail = 0;
    for (; first < argc && argv[first][0] == '-'; first++) {
        if (!strcmp(argv[first], "-t") && first + 1 < argc) limit = atoi(argv[++first]);
        else if (!strcmp(argv[first], "-q")) quiet = 1;
        else {
            fprintf(stderr, "usage: fuzz_replay [-t SECONDS] [-q] FILE...\n");
            return 2;
        }
    }
    for (int k = first; k < argc; k++) {
        const char *name = strrchr(argv[k], '/') ? strrchr(argv[k], '/') + 1 : argv[k];
        fflush(NULL); /* the child's exit() flushes its copy of the buffers */
        pid_t pid = fork();
        if (pid < 0) {
            perror("fuzz_replay: fork");
            return 2;
        }
        if (pid == 0) {
            alarm((unsigned)limit);
            /* exit(), not _exit(): the target's atexit handler removes its
             * temporary folder (one per child otherwise left in TMPDIR) */
            exit(replay_one(argv[k]));
        }
        int ws = 0;
        while (waitpid(pid, &ws, 0) < 0 && errno == EINTR) {}
        if (WIFEXITED(ws) && WEXITSTATUS(ws) == 0) {
            npass++;
            if (!quiet) printf("PASS fuzz.%s: read and compiled, clean status\n", name);
        } else {
            nfail++;
            if (WIFSIGNALED(ws) && WTERMSIG(ws) == SIGALRM)
                printf("FAIL fuzz.%s: no result within %d s (hang)\n", name, limit);
            else if (WIFSIGNALED(ws))
                printf("FAIL fuzz.%s: killed by signal %d (%s)\n", name, WTERMSIG(ws), strsignal(WTERMSIG(ws)));
            else
                printf("FAIL fuzz.%s: exit status %d\n", name, WEXITSTATUS(ws));
        }
    }
    if (quiet && npass) printf("PASS fuzz.seeds: %d inputs read and compiled, clean status\n", npass);
    return nfail ? 1 : 0;
}
