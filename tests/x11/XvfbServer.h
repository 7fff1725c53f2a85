// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
#pragma once

// A private X server for tests that need a display: Xvfb started with
// -displayfd, so it picks a free display number itself and tells it through
// a pipe once it accepts connections, and stopped when the object goes.
// CI needs no display of its own.

#include <X11/Xlib.h>

#include <csignal>
#include <string>

#include <fcntl.h>
#include <poll.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

namespace q3test {

class XvfbServer {
public:
    /// Starts Xvfb with one 1024x768 screen of depth 24 and opens it.
    /// display() is null when that failed; why() says why.
    XvfbServer()
    {
        int fds[2];
        if (pipe(fds) != 0) {
            m_why = "pipe failed";
            return;
        }
        m_pid = fork();
        if (m_pid == 0) {
            // The server goes with the test program, even one that crashed.
            prctl(PR_SET_PDEATHSIG, SIGTERM);
            close(fds[0]);
            const std::string fd = std::to_string(fds[1]);
            const int devnull = open("/dev/null", O_WRONLY);
            if (devnull >= 0) {
                dup2(devnull, 1);
                dup2(devnull, 2);
            }
            execlp("Xvfb", "Xvfb", "-displayfd", fd.c_str(), "-screen", "0", "1024x768x24", "-nolisten", "tcp",
                   static_cast<char*>(nullptr));
            _exit(127);
        }
        close(fds[1]);
        if (m_pid < 0) {
            close(fds[0]);
            m_why = "fork failed";
            return;
        }
        // Xvfb writes the display number and a newline when it is ready.
        std::string number;
        pollfd wait{fds[0], POLLIN, 0};
        while (poll(&wait, 1, 20000) > 0) {
            char c = 0;
            if (read(fds[0], &c, 1) != 1 || c == '\n')
                break;
            number += c;
        }
        close(fds[0]);
        if (number.empty()) {
            m_why = "Xvfb did not start (is the xvfb package installed? scripts/setup.sh installs it)";
            stop();
            return;
        }
        m_name = ":" + number;
        m_display = XOpenDisplay(m_name.c_str());
        if (m_display == nullptr) {
            m_why = "could not open Xvfb's display " + m_name;
            stop();
        }
    }
    ~XvfbServer()
    {
        if (m_display != nullptr)
            XCloseDisplay(m_display);
        stop();
    }
    XvfbServer(const XvfbServer&) = delete;
    XvfbServer& operator=(const XvfbServer&) = delete;

    Display* display() const { return m_display; }
    const std::string& why() const { return m_why; }

private:
    void stop()
    {
        if (m_pid > 0) {
            kill(m_pid, SIGTERM);
            waitpid(m_pid, nullptr, 0);
            m_pid = -1;
        }
    }

    pid_t m_pid = -1;
    Display* m_display = nullptr;
    std::string m_name;
    std::string m_why;
};

} // namespace q3test
