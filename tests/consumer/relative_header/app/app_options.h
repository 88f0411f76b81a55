/* The app's options header, named relative to app/CMakeLists.txt. */
#ifndef APP_OPTIONS_H
#define APP_OPTIONS_H

#define DARAN_LINE_MAX 200

#endif /* APP_OPTIONS_H */
