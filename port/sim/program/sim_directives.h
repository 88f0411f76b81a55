/* stdin's directives (`!advance`, `!power-cycle`, `!fault`, `!load`, `!can`,
 * `!#`), as --help lists them: a bad one is said on stderr (exit status 1)
 * and has no effect. */
#ifndef SIM_DIRECTIVES_H
#define SIM_DIRECTIVES_H

/* Run the directive @p line ("!name args...", NUL-terminated, no '\n';
 * split in place). */
void directive(char *line);

#endif /* SIM_DIRECTIVES_H */
