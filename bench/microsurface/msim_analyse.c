/* msim_analyse.c - the analyses (stub) */
#include <stdio.h>
int msim_cmd_error(const char *dir);
int msim_cmd_refit(const char *dir);
int msim_cmd_energy(const char *dir);
int msim_cmd_error(const char *dir) { (void)dir; return 0; }
int msim_cmd_refit(const char *dir) { (void)dir; return 0; }
int msim_cmd_energy(const char *dir) { (void)dir; return 0; }
