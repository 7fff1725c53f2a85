// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// q3view driven as a person drives it, with no person: the test starts its
// own Xvfb (tests/x11/XvfbServer.h; skipped where Xvfb is missing), runs
// q3view on it, sends real input events through the XTEST extension (the
// server treats them as the mouse and keyboard; libXtst.so.6 is opened at
// run time, and where it is missing the events go to the window with
// XSendEvent), waits for the line q3view prints for each event, and checks
// the saved pictures against pixel positions and colours computed here from
// the camera's geometry. Also: bad input gives the documented exit status
// and message, and the man page documents every option.

#include "Golden.h"

#include <gtest/gtest.h>

#include "XvfbServer.h"

#include <X11/Xutil.h>
#include <X11/keysym.h>

#include <dlfcn.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace {

std::string scratch(const std::string& name)
{
    return std::string(::testing::TempDir()) + "q3view_" + std::to_string(::getpid()) + "_" + name;
}

std::string slurp(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// Runs a shell command line; its exit status, and what it wrote to stderr
// and stdout.
int run(const std::string& command, std::string* errors = nullptr, std::string* output = nullptr)
{
    const std::string err = scratch("stderr.txt"), out = scratch("stdout.txt");
    const int raw = std::system((command + " > " + out + " 2> " + err).c_str());
    if (errors != nullptr)
        *errors = slurp(err);
    if (output != nullptr)
        *output = slurp(out);
    std::remove(err.c_str());
    std::remove(out.c_str());
    return WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
}

// A test model: the four sides and the top of a unit cube about the origin,
// each a polygon of its own flat colour, seen by the file's camera from 4
// units down the z axis with a field of view of 0.6 radians.
constexpr float kEyeDistance = 4.0f;
constexpr float kFieldOfView = 0.6f;
const char* const kPerspectiveCamera = "ViewAngleAspectCamera ( 0.6 1 )";
// 4 x 3 world units in view: 80 pixels a unit in a 320 x 240 window.
const char* const kOrthographicCamera = "OrthographicCamera ( -2 1.5 2 -1.5 )";
std::string cube(const char* camera)
{
    return std::string("3DMetafile ( 1 6 Normal )\nContainer (\n  ") + camera + R"(
  CameraPlacement ( 0 0 4  0 0 0  0 1 0 )
  CameraRange ( 1 10 )
  CameraViewPort ( -1 1 2 2 )
)
Container (
  Polygon ( 4  -0.5 -0.5 0.5  0.5 -0.5 0.5  0.5 0.5 0.5  -0.5 0.5 0.5 )
  Container ( AttributeSet ( ) DiffuseColor ( 1 0 0 ) )
)
Container (
  Polygon ( 4  0.5 -0.5 0.5  0.5 -0.5 -0.5  0.5 0.5 -0.5  0.5 0.5 0.5 )
  Container ( AttributeSet ( ) DiffuseColor ( 0 1 0 ) )
)
Container (
  Polygon ( 4  0.5 -0.5 -0.5  -0.5 -0.5 -0.5  -0.5 0.5 -0.5  0.5 0.5 -0.5 )
  Container ( AttributeSet ( ) DiffuseColor ( 0 0 1 ) )
)
Container (
  Polygon ( 4  -0.5 -0.5 -0.5  -0.5 -0.5 0.5  -0.5 0.5 0.5  -0.5 0.5 -0.5 )
  Container ( AttributeSet ( ) DiffuseColor ( 1 1 0 ) )
)
Container (
  Polygon ( 4  -0.5 0.5 0.5  0.5 0.5 0.5  0.5 0.5 -0.5  -0.5 0.5 -0.5 )
  Container ( AttributeSet ( ) DiffuseColor ( 0 1 1 ) )
)
)";
}

struct Rgb {
    int r, g, b;
};

Rgb pixel(const q3test::RgbaImage& image, int x, int y)
{
    const unsigned char* p = image.at(x, y);
    return Rgb{p[0], p[1], p[2]};
}

bool is(const Rgb& c, int r, int g, int b)
{
    return c.r == r && c.g == g && c.b == b;
}

// The background, mid grey: 0.5 of 255 either way it rounds.
bool isBackground(const Rgb& c)
{
    return c.r >= 127 && c.r <= 128 && c.g == c.r && c.b == c.r;
}

// The red pixels' extent: columns on row y, rows on column x.
int redRun(const q3test::RgbaImage& image, int y, int* first = nullptr)
{
    int count = 0, start = -1;
    for (int x = 0; x < image.width; ++x)
        if (is(pixel(image, x, y), 255, 0, 0)) {
            if (start < 0)
                start = x;
            ++count;
        }
    if (first != nullptr)
        *first = start;
    return count;
}

long redPixels(const q3test::RgbaImage& image)
{
    long count = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            count += is(pixel(image, x, y), 255, 0, 0) ? 1 : 0;
    return count;
}

int redColumn(const q3test::RgbaImage& image, int x)
{
    int count = 0;
    for (int y = 0; y < image.height; ++y)
        count += is(pixel(image, x, y), 255, 0, 0) ? 1 : 0;
    return count;
}

// Pixels across the window's shorter side per world unit at depth
// `distance` for the cube's camera (its field of view spans that side).
double pixelsPerUnit(int shorterSide, double distance)
{
    return shorterSide / 2.0 / (distance * std::tan(kFieldOfView / 2));
}

// Real input: XTEST's fake events, which the server handles as the mouse
// and keyboard (the window under the pointer gets them), or XSendEvent to
// the window where libXtst.so.6 is missing.
class Input {
public:
    Input(Display* display, Window window) : m_display(display), m_window(window)
    {
        void* library = dlopen("libXtst.so.6", RTLD_NOW | RTLD_LOCAL);
        if (library != nullptr) {
            m_motion = reinterpret_cast<MotionFn>(dlsym(library, "XTestFakeMotionEvent"));
            m_button = reinterpret_cast<ButtonFn>(dlsym(library, "XTestFakeButtonEvent"));
            m_key = reinterpret_cast<KeyFn>(dlsym(library, "XTestFakeKeyEvent"));
            auto query = reinterpret_cast<QueryFn>(dlsym(library, "XTestQueryExtension"));
            int event = 0, error = 0, major = 0, minor = 0;
            if (query == nullptr || !query(display, &event, &error, &major, &minor))
                m_motion = nullptr;
        }
    }
    bool usesXTest() const { return m_motion != nullptr && m_button != nullptr && m_key != nullptr; }

    void move(int x, int y)
    {
        m_x = x;
        m_y = y;
        if (usesXTest()) {
            m_motion(m_display, DefaultScreen(m_display), x, y, 0);
        } else {
            XEvent event = base(MotionNotify);
            send(event, PointerMotionMask);
        }
        XSync(m_display, False);
    }
    void button(unsigned number, bool press)
    {
        if (usesXTest()) {
            m_button(m_display, number, press ? True : False, 0);
        } else {
            XEvent event = base(press ? ButtonPress : ButtonRelease);
            event.xbutton.button = number;
            send(event, press ? ButtonPressMask : ButtonReleaseMask);
        }
        if (number <= 3)
            m_buttons = press ? m_buttons | (Button1Mask << (number - 1)) : m_buttons & ~(Button1Mask << (number - 1));
        XSync(m_display, False);
    }
    void drag(unsigned number, int x0, int y0, int x1, int y1)
    {
        move(x0, y0);
        button(number, true);
        const int steps = 4;
        for (int i = 1; i <= steps; ++i)
            move(x0 + (x1 - x0) * i / steps, y0 + (y1 - y0) * i / steps);
        button(number, false);
    }
    /// Holds a modifier key down (press) or lets it go.
    void modifier(KeySym symbol, unsigned mask, bool press)
    {
        if (usesXTest())
            m_key(m_display, XKeysymToKeycode(m_display, symbol), press ? True : False, 0);
        m_modifiers = press ? m_modifiers | mask : m_modifiers & ~mask;
        XSync(m_display, False);
    }
    void key(KeySym symbol)
    {
        const KeyCode code = XKeysymToKeycode(m_display, symbol);
        if (usesXTest()) {
            m_key(m_display, code, True, 0);
            m_key(m_display, code, False, 0);
        } else {
            XEvent event = base(KeyPress);
            event.xkey.keycode = code;
            send(event, KeyPressMask);
        }
        XSync(m_display, False);
    }

private:
    using MotionFn = int (*)(Display*, int, int, int, unsigned long);
    using ButtonFn = int (*)(Display*, unsigned, Bool, unsigned long);
    using KeyFn = int (*)(Display*, unsigned, Bool, unsigned long);
    using QueryFn = Bool (*)(Display*, int*, int*, int*, int*);

    // The window sits at the root's origin, so root and window coordinates
    // are the same.
    XEvent base(int type) const
    {
        XEvent event{};
        event.xkey.type = type;
        event.xkey.display = m_display;
        event.xkey.window = m_window;
        event.xkey.root = DefaultRootWindow(m_display);
        event.xkey.x = event.xkey.x_root = m_x;
        event.xkey.y = event.xkey.y_root = m_y;
        event.xkey.state = m_buttons | m_modifiers;
        event.xkey.same_screen = True;
        return event;
    }
    void send(XEvent& event, long mask) { XSendEvent(m_display, m_window, True, mask, &event); }

    Display* m_display;
    Window m_window;
    MotionFn m_motion = nullptr;
    ButtonFn m_button = nullptr;
    KeyFn m_key = nullptr;
    int m_x = 0, m_y = 0;
    unsigned m_buttons = 0;
    unsigned m_modifiers = 0;
};

// q3view running on a display, its standard output read line by line.
class Viewer {
public:
    Viewer(const std::string& display, const std::vector<std::string>& arguments)
    {
        int fds[2];
        if (pipe(fds) != 0)
            return;
        m_errors = scratch("viewer_stderr.txt");
        m_pid = fork();
        if (m_pid == 0) {
            close(fds[0]);
            dup2(fds[1], 1);
            if (freopen(m_errors.c_str(), "w", stderr) == nullptr)
                _exit(126);
            setenv("DISPLAY", display.c_str(), 1);
            std::vector<char*> argv{const_cast<char*>(Q3_VIEW_TOOL)};
            for (const std::string& argument : arguments)
                argv.push_back(const_cast<char*>(argument.c_str()));
            argv.push_back(nullptr);
            execv(Q3_VIEW_TOOL, argv.data());
            _exit(127);
        }
        close(fds[1]);
        m_out = fds[0];
    }
    ~Viewer()
    {
        if (m_pid > 0) {
            kill(m_pid, SIGTERM);
            waitpid(m_pid, nullptr, 0);
        }
        if (m_out >= 0)
            close(m_out);
        std::remove(m_errors.c_str());
    }
    Viewer(const Viewer&) = delete;
    Viewer& operator=(const Viewer&) = delete;

    /// The next line starting with prefix (lines before it are skipped),
    /// or "" when none comes within 20 seconds.
    std::string waitFor(const std::string& prefix)
    {
        const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
        for (;;) {
            const std::size_t end = m_buffer.find('\n');
            if (end != std::string::npos) {
                const std::string line = m_buffer.substr(0, end);
                m_buffer.erase(0, end + 1);
                m_log += line + "\n";
                if (line.compare(0, prefix.size(), prefix) == 0)
                    return line;
                continue;
            }
            const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline -
                                                                                    std::chrono::steady_clock::now());
            pollfd wait{m_out, POLLIN, 0};
            if (left.count() <= 0 || poll(&wait, 1, int(left.count())) <= 0)
                return "";
            char chunk[512];
            const ssize_t got = read(m_out, chunk, sizeof chunk);
            if (got <= 0)
                return "";
            m_buffer.append(chunk, std::size_t(got));
        }
    }
    /// Its exit status once it ends (-1 if it does not within 20 seconds).
    int exitStatus()
    {
        for (int i = 0; i < 400 && m_pid > 0; ++i) {
            int status = 0;
            if (waitpid(m_pid, &status, WNOHANG) == m_pid) {
                m_pid = -1;
                return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
            }
            usleep(50000);
        }
        return -1;
    }
    std::string errors() const { return slurp(m_errors); }
    const std::string& log() const { return m_log; }

private:
    pid_t m_pid = -1;
    int m_out = -1;
    std::string m_buffer, m_log, m_errors;
};

// "saved PATH WxH": reads PATH.
bool readSaved(const std::string& line, q3test::RgbaImage* image)
{
    const std::size_t first = line.find(' '), last = line.rfind(' ');
    if (first == std::string::npos || last <= first)
        return false;
    return q3test::readPng(line.substr(first + 1, last - first - 1), image);
}

// The window's pixels as the X server holds them.
q3test::RgbaImage windowImage(Display* display, Window window)
{
    XWindowAttributes attributes{};
    XGetWindowAttributes(display, window, &attributes);
    q3test::RgbaImage image(attributes.width, attributes.height);
    XImage* x = XGetImage(display, window, 0, 0, unsigned(attributes.width), unsigned(attributes.height), AllPlanes,
                          ZPixmap);
    if (x == nullptr)
        return q3test::RgbaImage();
    for (int row = 0; row < attributes.height; ++row)
        for (int column = 0; column < attributes.width; ++column) {
            const unsigned long value = XGetPixel(x, column, row);
            unsigned char* p = image.at(column, row);
            p[0] = (value >> 16) & 0xFF;
            p[1] = (value >> 8) & 0xFF;
            p[2] = value & 0xFF;
            p[3] = 255;
        }
    XDestroyImage(x);
    return image;
}

} // namespace

// Presses S and reads back the picture the viewer saves.
bool saveShot(Input& input, Viewer& viewer, q3test::RgbaImage* image)
{
    input.key(XK_s);
    return readSaved(viewer.waitFor("saved "), image);
}

// Presses R; the viewer's line about its camera.
std::string resetCamera(Input& input, Viewer& viewer)
{
    input.key(XK_r);
    return viewer.waitFor("camera");
}

// Presses Q, expects a clean exit, and removes the model and the `shots`
// pictures saved under `prefix`.
void quitAndRemove(Input& input, Viewer& viewer, const std::string& model, const std::string& prefix, int shots)
{
    input.key(XK_q);
    EXPECT_EQ(viewer.exitStatus(), 0);
    EXPECT_EQ(viewer.errors(), "");
    std::remove(model.c_str());
    for (int n = 1; n <= shots; ++n)
        std::remove((prefix + "-" + std::to_string(n) + ".png").c_str());
}

TEST(Q3View, MouseAndKeysChangeThePictureAsComputed)
{
    q3test::XvfbServer server;
    if (server.display() == nullptr)
        GTEST_SKIP() << server.why();
    Display* display = server.display();
    const std::string model = scratch("cube.3dmf");
    std::ofstream(model) << cube(kPerspectiveCamera);
    const std::string prefix = scratch("shot");
    Viewer viewer(DisplayString(display), {model, "--size", "320x240", "--save", prefix});

    const std::string shown = viewer.waitFor("window ");
    ASSERT_NE(shown, "") << viewer.errors();
    EXPECT_NE(shown.find(" 320x240"), std::string::npos) << shown;
    const Window window = Window(std::strtoul(shown.c_str() + 7, nullptr, 16));
    Input input(display, window);
    std::printf("input through %s\n", input.usesXTest() ? "XTEST" : "XSendEvent");

    // Picking: the front face at the centre, nothing in the corner.
    input.move(160, 120);
    EXPECT_EQ(viewer.waitFor("pick "), "pick Polygon") << viewer.log();
    char* title = nullptr;
    ASSERT_TRUE(XFetchName(display, window, &title));
    EXPECT_EQ(std::string(title), "q3view: " + model + " - Polygon");
    XFree(title);
    input.move(3, 3);
    EXPECT_EQ(viewer.waitFor("pick "), "pick nothing") << viewer.log();

    // Flat colours, so that each face shows its diffuse colour exactly.
    input.key(XK_l);
    ASSERT_EQ(viewer.waitFor("lights"), "lights off");
    input.key(XK_s);
    q3test::RgbaImage first;
    const std::string saved = viewer.waitFor("saved ");
    ASSERT_TRUE(readSaved(saved, &first)) << saved << viewer.errors();
    EXPECT_NE(saved.find(" 320x240"), std::string::npos) << saved;
    ASSERT_EQ(first.width, 320);
    ASSERT_EQ(first.height, 240);
    // The saved picture is the window's.
    EXPECT_EQ(q3test::countDifferingPixels(first, windowImage(display, window)), 0);
    EXPECT_TRUE(is(pixel(first, 160, 120), 255, 0, 0));
    EXPECT_TRUE(isBackground(pixel(first, 2, 2)));
    // The front face, 1 wide at 3.5 from the eye, is this many pixels wide
    // and high (one pixel either way for the edges' rounding).
    const double side = pixelsPerUnit(240, kEyeDistance - 0.5);
    EXPECT_NEAR(redRun(first, 120), side, 1.5);
    EXPECT_NEAR(redColumn(first, 160), side, 1.5);

    // A left drag of 200 pixels to the right turns the model a quarter turn
    // (pi/400 a pixel) as if grabbed: its left side (yellow) comes to face
    // the camera.
    input.drag(1, 60, 120, 260, 120);
    q3test::RgbaImage turned;
    ASSERT_TRUE(saveShot(input, viewer, &turned));
    EXPECT_TRUE(is(pixel(turned, 160, 120), 255, 255, 0));
    EXPECT_EQ(redRun(turned, 120), 0);
    // ... and the same drag back gives the first picture again.
    input.drag(1, 260, 120, 60, 120);
    q3test::RgbaImage back;
    ASSERT_TRUE(saveShot(input, viewer, &back));
    EXPECT_EQ(q3test::countDifferingPixels(first, back), 0);

    // Dragging 160 pixels down tips the top toward the camera by 0.4 pi: the
    // eye is then at 4 (0, sin 0.4pi, cos 0.4pi), and the ray through the
    // centre meets the top face (cyan) at z = 0.5 / tan(0.4 pi) < 0.5.
    input.drag(1, 160, 40, 160, 200);
    q3test::RgbaImage tipped;
    ASSERT_TRUE(saveShot(input, viewer, &tipped));
    EXPECT_TRUE(is(pixel(tipped, 160, 120), 0, 255, 255));

    // Reset: the first picture exactly.
    ASSERT_EQ(resetCamera(input, viewer), "camera reset");
    q3test::RgbaImage reset;
    ASSERT_TRUE(saveShot(input, viewer, &reset));
    EXPECT_EQ(q3test::countDifferingPixels(first, reset), 0);

    // One wheel step up brings the eye to 0.9 x 4 = 3.6 from the centre:
    // the front face is then 3.1 away and this much wider.
    input.move(160, 120);
    input.button(Button4, true);
    input.button(Button4, false);
    q3test::RgbaImage zoomed;
    ASSERT_TRUE(saveShot(input, viewer, &zoomed));
    const double zoomedSide = pixelsPerUnit(240, 0.9 * kEyeDistance - 0.5);
    EXPECT_NEAR(redRun(zoomed, 120), zoomedSide, 1.5);
    EXPECT_NEAR(redColumn(zoomed, 160), zoomedSide, 1.5);

    // A right drag of 48 pixels moves the point of interest's plane 48
    // pixels; the front face, nearer (3.5 against 4), moves 48 x 4 / 3.5.
    ASSERT_EQ(resetCamera(input, viewer), "camera reset");
    input.drag(3, 100, 120, 148, 120);
    q3test::RgbaImage panned;
    ASSERT_TRUE(saveShot(input, viewer, &panned));
    int before = 0, after = 0;
    redRun(first, 120, &before);
    redRun(panned, 120, &after);
    EXPECT_NEAR(after - before, 48.0 * kEyeDistance / (kEyeDistance - 0.5), 1.0);
    EXPECT_NEAR(redRun(panned, 120), side, 1.5);
    // The middle button, and the left one with Shift, move it the same.
    ASSERT_EQ(resetCamera(input, viewer), "camera reset");
    input.drag(2, 100, 120, 148, 120);
    q3test::RgbaImage middle;
    ASSERT_TRUE(saveShot(input, viewer, &middle));
    EXPECT_EQ(q3test::countDifferingPixels(panned, middle), 0);
    ASSERT_EQ(resetCamera(input, viewer), "camera reset");
    input.modifier(XK_Shift_L, ShiftMask, true);
    input.drag(1, 100, 120, 148, 120);
    input.modifier(XK_Shift_L, ShiftMask, false);
    q3test::RgbaImage shifted;
    ASSERT_TRUE(saveShot(input, viewer, &shifted));
    EXPECT_EQ(q3test::countDifferingPixels(panned, shifted), 0);
    ASSERT_EQ(resetCamera(input, viewer), "camera reset");

    // The wireframe renderer: edges only, the centre is background.
    input.key(XK_w);
    ASSERT_EQ(viewer.waitFor("renderer"), "renderer wireframe");
    q3test::RgbaImage wire;
    ASSERT_TRUE(saveShot(input, viewer, &wire));
    EXPECT_GT(q3test::countDifferingPixels(first, wire), 1000);
    EXPECT_TRUE(isBackground(pixel(wire, 160, 120)));
    EXPECT_GT(redPixels(wire), 0);
    // The edges fill style under the interactive renderer: edges too.
    input.key(XK_i);
    ASSERT_EQ(viewer.waitFor("renderer"), "renderer interactive");
    input.key(XK_e);
    ASSERT_EQ(viewer.waitFor("fill"), "fill edges");
    q3test::RgbaImage edges;
    ASSERT_TRUE(saveShot(input, viewer, &edges));
    EXPECT_TRUE(isBackground(pixel(edges, 160, 120)));
    EXPECT_GT(redPixels(edges), 0);
    // Points: the vertices alone.
    input.key(XK_p);
    ASSERT_EQ(viewer.waitFor("fill"), "fill points");
    q3test::RgbaImage points;
    ASSERT_TRUE(saveShot(input, viewer, &points));
    EXPECT_TRUE(isBackground(pixel(points, 160, 120)));
    EXPECT_EQ(redRun(points, 120), 0);
    long drawn = 0;
    for (int y = 0; y < points.height; ++y)
        for (int x = 0; x < points.width; ++x)
            drawn += isBackground(pixel(points, x, y)) ? 0 : 1;
    EXPECT_GE(drawn, 4);
    EXPECT_LT(drawn, 100);
    input.key(XK_f);
    ASSERT_EQ(viewer.waitFor("fill"), "fill filled");
    // Lights on again: shaded, so the picture changes.
    input.key(XK_l);
    ASSERT_EQ(viewer.waitFor("lights"), "lights on");
    q3test::RgbaImage lit;
    ASSERT_TRUE(saveShot(input, viewer, &lit));
    EXPECT_FALSE(is(pixel(lit, 160, 120), 255, 0, 0));
    EXPECT_GT(pixel(lit, 160, 120).r, pixel(lit, 160, 120).g);
    input.key(XK_l);
    ASSERT_EQ(viewer.waitFor("lights"), "lights off");

    // The window's size followed: a 400 x 300 window is filled and the face
    // keeps its shape (the field of view spans the shorter side, 300).
    XResizeWindow(display, window, 400, 300);
    XSync(display, False);
    ASSERT_EQ(viewer.waitFor("size"), "size 400x300");
    input.key(XK_s);
    const std::string resizedLine = viewer.waitFor("saved ");
    EXPECT_NE(resizedLine.find(" 400x300"), std::string::npos) << resizedLine;
    q3test::RgbaImage resized;
    ASSERT_TRUE(readSaved(resizedLine, &resized));
    ASSERT_EQ(resized.width, 400);
    ASSERT_EQ(resized.height, 300);
    EXPECT_EQ(q3test::countDifferingPixels(resized, windowImage(display, window)), 0);
    const double resizedSide = pixelsPerUnit(300, kEyeDistance - 0.5);
    EXPECT_NEAR(redRun(resized, 150), resizedSide, 1.5);
    EXPECT_NEAR(redColumn(resized, 200), resizedSide, 1.5);
    EXPECT_TRUE(isBackground(pixel(resized, 398, 298)));

    quitAndRemove(input, viewer, model, prefix, 16);
}

TEST(Q3View, TheWheelScalesAnOrthographicCamerasRectangle)
{
    q3test::XvfbServer server;
    if (server.display() == nullptr)
        GTEST_SKIP() << server.why();
    Display* display = server.display();
    const std::string model = scratch("ortho_cube.3dmf");
    std::ofstream(model) << cube(kOrthographicCamera);
    const std::string prefix = scratch("ortho");
    Viewer viewer(DisplayString(display), {model, "--size", "320x240", "--save", prefix, "--script", "l s"});
    const std::string shown = viewer.waitFor("window ");
    ASSERT_NE(shown, "") << viewer.errors();
    const Window window = Window(std::strtoul(shown.c_str() + 7, nullptr, 16));
    Input input(display, window);
    q3test::RgbaImage first, zoomed, panned;
    ASSERT_TRUE(readSaved(viewer.waitFor("saved "), &first));
    // 80 pixels a unit: the front face is 80 pixels square.
    EXPECT_NEAR(redRun(first, 120), 80.0, 1.0);
    EXPECT_NEAR(redColumn(first, 160), 80.0, 1.0);
    // A wheel step shows 0.9 times the rectangle: 80 / 0.9 pixels a unit.
    input.move(160, 120);
    input.button(Button4, true);
    input.button(Button4, false);
    ASSERT_TRUE(saveShot(input, viewer, &zoomed));
    EXPECT_NEAR(redRun(zoomed, 120), 80.0 / 0.9, 1.0);
    EXPECT_NEAR(redColumn(zoomed, 160), 80.0 / 0.9, 1.0);
    // Moving it: every depth moves as far as the mouse.
    ASSERT_EQ(resetCamera(input, viewer), "camera reset");
    input.drag(3, 100, 120, 148, 100);
    ASSERT_TRUE(saveShot(input, viewer, &panned));
    int before = 0, after = 0;
    redRun(first, 120, &before);
    redRun(panned, 100, &after);
    EXPECT_NEAR(after - before, 48, 1);
    EXPECT_NEAR(redColumn(panned, 160 + 48) - redColumn(first, 160), 0, 1);
    quitAndRemove(input, viewer, model, prefix, 3);
}

TEST(Q3View, TheFilesCameraIsUsedUnlessFitCameraIsAsked)
{
    q3test::XvfbServer server;
    if (server.display() == nullptr)
        GTEST_SKIP() << server.why();
    // camera_scene.3dmf: a red square at the origin, a green one at x = 10,
    // and a camera close in front of the green one. Its camera shows the
    // green square in the middle; a fitted camera looks at the middle of
    // both, x = 5, where there is nothing.
    const std::string prefix = scratch("camera");
    const std::string command = std::string("DISPLAY=") + DisplayString(server.display()) + " " + Q3_VIEW_TOOL +
                                " " + Q3_TEST_DATA_DIR + "/camera_scene.3dmf --size 160x120 --script 'l s q' --save ";
    std::string errors;
    ASSERT_EQ(run(command + prefix + "_file", &errors), 0) << errors;
    ASSERT_EQ(run(command + prefix + "_fit --fit-camera", &errors), 0) << errors;
    q3test::RgbaImage file, fit;
    ASSERT_TRUE(q3test::readPng(prefix + "_file-1.png", &file));
    ASSERT_TRUE(q3test::readPng(prefix + "_fit-1.png", &fit));
    EXPECT_TRUE(is(pixel(file, 80, 60), 0, 255, 0));
    EXPECT_TRUE(isBackground(pixel(fit, 80, 60)));
    EXPECT_EQ(redRun(file, 60), 0);
    EXPECT_GT(redRun(fit, 60), 0);
    std::remove((prefix + "_file-1.png").c_str());
    std::remove((prefix + "_fit-1.png").c_str());
}

TEST(Q3View, ALostConnectionIsExitStatusThreeWithAMessage)
{
    q3test::XvfbServer server;
    if (server.display() == nullptr)
        GTEST_SKIP() << server.why();
    Display* display = server.display();
    Viewer viewer(DisplayString(display), {std::string(Q3_TEST_DATA_DIR) + "/scene.3dmf", "--size", "64x48"});
    const std::string shown = viewer.waitFor("window ");
    ASSERT_NE(shown, "") << viewer.errors();
    // The server closes q3view's connection, as when the display goes away.
    XKillClient(display, Window(std::strtoul(shown.c_str() + 7, nullptr, 16)));
    XSync(display, False);
    EXPECT_EQ(viewer.exitStatus(), 3);
    EXPECT_NE(viewer.errors().find("the connection to the X display"), std::string::npos) << viewer.errors();
}

TEST(Q3View, AScriptDrawsSavesAndQuitsWithNoOneAtTheKeyboard)
{
    q3test::XvfbServer server;
    if (server.display() == nullptr)
        GTEST_SKIP() << server.why();
    const std::string prefix = scratch("script");
    std::string errors, output;
    EXPECT_EQ(run(std::string("DISPLAY=") + DisplayString(server.display()) + " " + Q3_VIEW_TOOL + " " +
                      Q3_TEST_DATA_DIR + "/scene.3dmf --size 200x150 --save " + prefix + " --script 's w s r q'",
                  &errors, &output),
              0);
    EXPECT_EQ(errors, "");
    EXPECT_NE(output.find("saved " + prefix + "-1.png 200x150\n"), std::string::npos) << output;
    EXPECT_NE(output.find("renderer wireframe\n"), std::string::npos) << output;
    q3test::RgbaImage filled, wire;
    ASSERT_TRUE(q3test::readPng(prefix + "-1.png", &filled));
    ASSERT_TRUE(q3test::readPng(prefix + "-2.png", &wire));
    EXPECT_EQ(filled.width, 200);
    EXPECT_EQ(filled.height, 150);
    EXPECT_GT(q3test::countDifferingPixels(filled, wire), 500);
    for (const char* n : {"-1.png", "-2.png"})
        std::remove((prefix + n).c_str());
}

TEST(Q3View, BadInputIsAClearMessageAndItsExitStatus)
{
    const std::string tool = Q3_VIEW_TOOL;
    const std::string scene = std::string(Q3_TEST_DATA_DIR) + "/scene.3dmf";
    std::string errors, output;
    EXPECT_EQ(run(tool, &errors), 1);
    EXPECT_NE(errors.find("usage: q3view"), std::string::npos) << errors;
    EXPECT_EQ(run(tool + " " + scene + " --size 0x10", &errors), 1);
    EXPECT_EQ(run(tool + " " + scene + " --renderer fancy", &errors), 1);
    EXPECT_EQ(run(tool + " " + scene + " --no-such-option", &errors), 1);
    EXPECT_EQ(run(tool + " --help", &errors, &output), 0);
    EXPECT_NE(output.find("usage: q3view"), std::string::npos);
    EXPECT_EQ(errors, "");

    // The file is read before a display is looked for.
    const std::string missing = scratch("missing.3dmf");
    EXPECT_EQ(run("env -u DISPLAY " + tool + " " + missing, &errors), 2);
    EXPECT_NE(errors.find("cannot open " + missing), std::string::npos) << errors;
    const std::string garbage = scratch("garbage.3dmf");
    std::ofstream(garbage) << "this is not a metafile\n";
    EXPECT_EQ(run("env -u DISPLAY " + tool + " " + garbage, &errors), 2);
    EXPECT_NE(errors.find("is not a 3DMF file"), std::string::npos) << errors;
    std::remove(garbage.c_str());

    EXPECT_EQ(run("env -u DISPLAY " + tool + " " + scene, &errors), 3);
    EXPECT_NE(errors.find("DISPLAY is not set"), std::string::npos) << errors;
    EXPECT_EQ(run("DISPLAY=:4095 " + tool + " " + scene, &errors), 3);
    EXPECT_NE(errors.find("cannot open the X display :4095"), std::string::npos) << errors;
}

TEST(Q3View, TheManPageDocumentsEveryOptionAndExitStatus)
{
    const std::string roff = slurp(std::string(Q3_MAN_DIR) + "/q3view.1");
    ASSERT_FALSE(roff.empty());
    std::string text = roff;
    for (std::size_t at = text.find("\\-"); at != std::string::npos; at = text.find("\\-", at))
        text.erase(at, 1);
    std::string output;
    ASSERT_EQ(run(std::string(Q3_VIEW_TOOL) + " --help", nullptr, &output), 0);
    int options = 0;
    for (std::size_t at = output.find("--"); at != std::string::npos; at = output.find("--", at + 2)) {
        std::size_t end = at + 2;
        while (end < output.size() && (std::isalnum(static_cast<unsigned char>(output[end])) || output[end] == '-'))
            ++end;
        const std::string option = output.substr(at, end - at);
        ++options;
        EXPECT_NE(text.find(option), std::string::npos) << option << " is in --help but not in q3view.1";
    }
    EXPECT_GE(options, 6);
    for (const char* section : {".SH SYNOPSIS", ".SH OPTIONS", ".SH EXIT STATUS", ".SH EXAMPLES", ".SH SEE ALSO"})
        EXPECT_NE(roff.find(section), std::string::npos) << section;
    for (const char* status : {"0 done", "1 bad arguments", "2 the model cannot be read", "3 no X display",
                               "4 the model cannot be drawn"})
        EXPECT_NE(output.find(status), std::string::npos) << status;
    for (int status = 0; status <= 4; ++status)
        EXPECT_NE(roff.find(".B " + std::to_string(status) + "\n"), std::string::npos) << status;
}
