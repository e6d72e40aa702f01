/* ricochet fit: contact parameters calibrated to measured signals by
 * nonlinear least squares (docs/calibration.md). */
#ifndef RC_CLI_FIT_H
#define RC_CLI_FIT_H

/* `ricochet fit DECK --data FILE.csv --free CARD:FIELD=START[,LO:HI] ...`:
 * argv[1] is "fit". Returns the program's exit code: 0 converged, 1 not
 * converged within the iterations, 2 input error (nothing run), 3 the
 * simulation at the start failed, 4 a file could not be written. */
int rc_cli_fit(int argc, char **argv);

#endif /* RC_CLI_FIT_H */
