/* ricochet sens: derivatives of body positions and velocities with respect
 * to deck fields, by forward sensitivity analysis (docs/calibration.md,
 * "Sensitivities"). */
#ifndef RC_CLI_SENS_H
#define RC_CLI_SENS_H

/* `ricochet sens DECK --param CARD:FIELD=VALUE ... --at T[,T...]`: argv[1]
 * is "sens". Returns the program's exit code: 0 done, 2 input error, 3 the
 * run failed. */
int rc_cli_sens(int argc, char **argv);

#endif /* RC_CLI_SENS_H */
