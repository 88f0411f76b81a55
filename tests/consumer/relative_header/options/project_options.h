/* The project's options header, named relative to its top-level folder. */
#ifndef PROJECT_OPTIONS_H
#define PROJECT_OPTIONS_H

#define DARAN_LINE_MAX 96

#endif /* PROJECT_OPTIONS_H */
