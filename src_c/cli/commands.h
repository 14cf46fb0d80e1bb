/* commands.h — the subcommands of `capbridge`, one function each (in cmd_NAME.c).
 * argv[0] is the subcommand name; the function handles --help itself and returns the
 * exit code (0 success, 1 run-time failure, 2 wrong command line). */
#ifndef CAPBRIDGE_CLI_COMMANDS_H
#define CAPBRIDGE_CLI_COMMANDS_H

int cmd_force(int argc, char **argv);
int cmd_curve(int argc, char **argv);
int cmd_rupture(int argc, char **argv);
int cmd_exact(int argc, char **argv);
int cmd_pulloff(int argc, char **argv);
int cmd_replay(int argc, char **argv);
int cmd_reference(int argc, char **argv);
int cmd_report(int argc, char **argv);
int cmd_bench(int argc, char **argv);

#endif
