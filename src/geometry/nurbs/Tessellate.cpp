// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
//
// Parameter sampling for the three subdivision methods of the article's section
// "CONTROLLING SUBDIVISION": a fixed number of segments between each pair of joints
// (constant), or segments no longer than c1 measured in world or screen space.
//
// Both methods work span by span on the rational Bezier form (Bezier.cpp), so every
// vertex is an exact evaluation of the curve in double, rounded to float once.
//
// Constant: m segments per span at u_j = j/m, sampled with one Bernstein table for the
// whole curve; the end vertex of a span is the start vertex of the next, emitted once.
//
// Adaptive: a chord of a smooth curve is no longer than the arc it spans, so points
// placed uniformly in (mapped) arc length, L/n apart with n = ceil(L/c1), give chords of
// at most c1. Arc length is estimated with chord sums, first over probeSegmentsPerSpan
// probes per span (which also find where the mapping fails and give the totals needed
// to respect kMaxSegments before anything is emitted), then, where a run needs more
// segments than half its probes, over a finer table of about 2n samples; points are
// placed by inverting the piecewise-linear cumulative length. Estimation is only a
// guide: every chord is measured between its mapped end points and halved in
// parameter while it is longer than c1, so the bound holds wherever the mapping does.
// The padding kLengthPadding keeps such halvings rare, which is what keeps the count
// near the minimum.

#include "geometry/nurbs/Tessellate.h"

#include "geometry/nurbs/Knots.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace q3::nurbs {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// Curves small enough are converted to Bezier form once up front rather than once per
// pass; above this many Bezier points (8 MB) spans are converted as they are visited.
constexpr std::size_t kConvertOnceLimit = std::size_t{1} << 18;

class FormSpans {
public:
    explicit FormSpans(const BezierForm& form) : m_form(form) {}
    std::size_t count() const { return m_form.spanCount(); }
    unsigned order() const { return m_form.order(); }
    const Span& span(std::size_t s) const { return m_form.span(s); }
    const Point4* points(std::size_t s) { return m_form.spanPoints(s); }

private:
    const BezierForm& m_form;
};

class CurveSpans {
public:
    explicit CurveSpans(const CurveRef& curve) : m_curve(curve), m_spans(nonEmptySpans(curve)) {}
    std::size_t count() const { return m_spans.size(); }
    unsigned order() const { return m_curve.order; }
    const Span& span(std::size_t s) const { return m_spans[s]; }
    const Point4* points(std::size_t s)
    {
        spanToBezier(m_curve, m_spans[s].knotIndex, m_scratch);
        return m_scratch;
    }

private:
    CurveRef m_curve;
    std::vector<Span> m_spans;
    Point4 m_scratch[kMaxOrder];
};

double spanParameter(const Span& span, double u)
{
    return u >= 1.0 ? span.end : span.start + (span.end - span.start) * u;
}

bool sameVertex(const float* a, const float* b)
{
    return a[0] == b[0] && a[1] == b[1] && a[2] == b[2];
}

// Appends vertices, dropping one equal to its predecessor. The first vertex always
// stays (with the domain start); for a later repeat the newer parameter is kept, so
// the final vertex carries the domain end.
class PolylineBuilder {
public:
    explicit PolylineBuilder(TessellatedCurve& out) : m_out(out) {}

    void add(double t, const Point3& p)
    {
        const float v[3] = {float(p.x), float(p.y), float(p.z)};
        const std::size_t count = m_out.parameters.size();
        if (count > 0 && sameVertex(v, &m_out.vertices[3 * (count - 1)])) {
            if (count > 1) {
                m_out.parameters.back() = t;
            }
            return;
        }
        m_out.vertices.insert(m_out.vertices.end(), v, v + 3);
        m_out.parameters.push_back(t);
    }

private:
    TessellatedCurve& m_out;
};

// The same rule as PolylineBuilder, applied in place after bulk sampling.
void dropRepeats(TessellatedCurve& out)
{
    const std::size_t count = out.parameters.size();
    if (count < 2) {
        return;
    }
    float* v = out.vertices.data();
    double* t = out.parameters.data();
    std::size_t kept = 1;
    for (std::size_t r = 1; r < count; ++r) {
        if (sameVertex(v + 3 * r, v + 3 * (kept - 1))) {
            if (kept > 1) {
                t[kept - 1] = t[r];
            }
            continue;
        }
        if (kept != r) {
            v[3 * kept] = v[3 * r];
            v[3 * kept + 1] = v[3 * r + 1];
            v[3 * kept + 2] = v[3 * r + 2];
            t[kept] = t[r];
        }
        ++kept;
    }
    out.vertices.resize(3 * kept);
    out.parameters.resize(kept);
}

template <typename Spans>
TessellatedCurve constantImpl(Spans& spans, std::uint32_t requested)
{
    TessellatedCurve out;
    const std::size_t spanCount = spans.count();
    if (spanCount == 0) {
        return out;
    }
    std::uint32_t m = std::max<std::uint32_t>(requested, 1);
    m = std::min(m, kMaxSegmentsPerSpan);
    const std::size_t perSpanBudget = std::max<std::size_t>(kMaxSegments / spanCount, 1);
    m = std::uint32_t(std::min<std::size_t>(m, perSpanBudget));
    out.substituted = m != requested;
    out.effectiveValue = m;

    const BernsteinTable table(spans.order(), m);
    std::vector<double> fraction(m);
    for (std::uint32_t j = 0; j < m; ++j) {
        fraction[j] = double(j) / double(m);
    }
    const std::size_t vertexCount = spanCount * m + 1;
    out.vertices.resize(3 * vertexCount);
    out.parameters.resize(vertexCount);
    float* v = out.vertices.data();
    double* t = out.parameters.data();
    const Point4* points = nullptr;
    for (std::size_t s = 0; s < spanCount; ++s) {
        points = spans.points(s);
        sampleBezier(points, table, 0, m, v + 3 * s * m);
        const Span& span = spans.span(s);
        const double width = span.end - span.start;
        for (std::uint32_t j = 0; j < m; ++j) {
            t[s * m + j] = span.start + width * fraction[j];
        }
    }
    sampleBezier(points, table, m, 1, v + 3 * (vertexCount - 1));
    t[vertexCount - 1] = spans.span(spanCount - 1).end;
    dropRepeats(out);
    return out;
}

struct Sample {
    double u = 0.0;
    Point3 point;
    Point3 image;
    bool mapped = false;
};

// A maximal stretch of probe intervals of one span that are all measurable (both
// ends mapped) or all not.
struct Run {
    std::size_t span = 0;
    std::uint32_t first = 0;
    std::uint32_t last = 0;
    bool measurable = false;
    double length = 0.0;
};

double distance(const Point3& a, const Point3& b)
{
    const double dx = b.x - a.x;
    const double dy = b.y - a.y;
    const double dz = b.z - a.z;
    return std::sqrt(dx * dx + dy * dy + dz * dz);
}

template <typename Spans>
class Adaptive {
public:
    Adaptive(Spans& spans, const PointMapping& mapping, TessellatedCurve& out)
        : m_spans(spans), m_mapping(mapping), m_out(out), m_builder(out), m_order(spans.order()),
          m_probeSegments(probeSegmentsPerSpan(m_order)), m_probeTable(m_order, m_probeSegments),
          m_probes(m_probeSegments + 1)
    {
    }

    void run(double c1)
    {
        const std::size_t spanCount = m_spans.count();
        if (spanCount == 0) {
            return;
        }
        collectRuns();
        chooseLength(c1);
        if (m_onePerSpan) {
            emitOnePerSpan();
        } else {
            emitRuns();
        }
    }

private:
    bool mapPoint(const Point3& p, Point3& image) const
    {
        if (!m_mapping(p, image)) {
            return false;
        }
        return std::isfinite(image.x) && std::isfinite(image.y) && std::isfinite(image.z);
    }

    Sample makeSample(double u) const
    {
        Sample sample;
        sample.u = u;
        sample.point = project(evaluateBezier(m_points, m_order, u));
        sample.mapped = mapPoint(sample.point, sample.image);
        return sample;
    }

    void probeSpan(std::size_t s)
    {
        m_points = m_spans.points(s);
        double xyz[3 * (kMaxOrder + 1)];
        sampleBezier(m_points, m_probeTable, 0, m_probeSegments + 1, xyz);
        for (std::uint32_t j = 0; j <= m_probeSegments; ++j) {
            Sample& sample = m_probes[j];
            sample.u = double(j) / double(m_probeSegments);
            sample.point = Point3{xyz[3 * j], xyz[3 * j + 1], xyz[3 * j + 2]};
            sample.mapped = mapPoint(sample.point, sample.image);
        }
    }

    static bool measurable(const Sample& a, const Sample& b, double& length)
    {
        if (!a.mapped || !b.mapped) {
            return false;
        }
        length = distance(a.image, b.image);
        return std::isfinite(length);
    }

    void collectRuns()
    {
        double lengths[kMaxOrder + 1];
        bool ok[kMaxOrder + 1];
        for (std::size_t s = 0; s < m_spans.count(); ++s) {
            probeSpan(s);
            for (std::uint32_t j = 0; j < m_probeSegments; ++j) {
                lengths[j] = 0.0;
                ok[j] = measurable(m_probes[j], m_probes[j + 1], lengths[j]);
            }
            for (std::uint32_t j = 0; j < m_probeSegments;) {
                Run run;
                run.span = s;
                run.first = j;
                run.measurable = ok[j];
                while (j < m_probeSegments && ok[j] == run.measurable) {
                    run.length += run.measurable ? lengths[j] : 0.0;
                    ++j;
                }
                run.last = j;
                if (run.measurable) {
                    ++m_measurableRuns;
                    m_totalLength += run.length;
                } else {
                    m_unmeasurableIntervals += run.last - run.first;
                }
                m_runs.push_back(run);
            }
        }
    }

    static std::size_t segmentsFor(double length, double c)
    {
        if (!(length > 0.0) || c == kInfinity) {
            return 1;
        }
        const double q = std::ceil(length * kLengthPadding / c);
        if (!(q < double(kMaxSegments))) {
            return kMaxSegments + 1;
        }
        return std::max<std::size_t>(std::size_t(q), 1);
    }

    std::size_t wanted(double c) const
    {
        std::size_t total = m_unmeasurableIntervals;
        for (const Run& run : m_runs) {
            if (run.measurable) {
                total += segmentsFor(run.length, c);
            }
        }
        return total;
    }

    void chooseLength(double c1)
    {
        const bool usable = c1 > 0.0;
        if (usable) {
            m_planned = wanted(c1);
            if (m_planned <= kPlacementBudget) {
                m_c = c1;
                m_out.effectiveValue = c1;
                return;
            }
        }
        m_out.substituted = true;
        const std::size_t fixed = m_unmeasurableIntervals + m_measurableRuns;
        if (fixed >= kPlacementBudget) {
            m_onePerSpan = true;
            m_c = kInfinity;
            m_out.effectiveValue = kInfinity;
            m_planned = m_spans.count();
            return;
        }
        // Each run needs at most padding * length / c + 1 segments, so this c fits.
        const std::size_t room = kPlacementBudget - fixed;
        double c = m_totalLength > 0.0 ? m_totalLength * kLengthPadding / double(room) : kInfinity;
        if (!(c > 0.0)) {
            c = kInfinity;
        }
        m_planned = wanted(c);
        for (int attempt = 0; attempt < 64 && m_planned > kPlacementBudget; ++attempt) {
            c *= 1.0 + 1.0 / 1024.0;
            m_planned = wanted(c);
        }
        m_c = c;
        m_out.effectiveValue = c;
    }

    void emit(const Sample& sample)
    {
        m_builder.add(spanParameter(m_spans.span(m_currentSpan), sample.u), sample.point);
    }

    bool tooLong(const Sample& a, const Sample& b) const
    {
        if (!a.mapped || !b.mapped) {
            return false;
        }
        const double d = distance(a.image, b.image);
        return std::isfinite(d) && d > m_c;
    }

    // Emits a and every point bisection inserts before b; b itself is left to the caller.
    void emitChord(const Sample& a, const Sample& b)
    {
        emit(a);
        m_stack.clear();
        m_stack.push_back(Pending{b, 0});
        Sample left = a;
        for (;;) {
            const Sample right = m_stack.back().sample;
            const unsigned depth = m_stack.back().depth;
            if (tooLong(left, right)) {
                const double um = 0.5 * (left.u + right.u);
                const bool splittable = depth < kMaxBisectionDepth && left.u < um && um < right.u;
                if (splittable && m_planned + m_extra < kMaxSegments) {
                    m_stack.back().depth = depth + 1;
                    m_stack.push_back(Pending{makeSample(um), depth + 1});
                    ++m_extra;
                    continue;
                }
                m_out.capped = true;
            }
            double length = 0.0;
            if (!measurable(left, right, length)) {
                ++m_out.unmeasuredSegments;
            }
            m_stack.pop_back();
            if (m_stack.empty()) {
                return;
            }
            emit(right);
            left = right;
        }
    }

    void emitMeasurableRun(const Run& run)
    {
        const Sample& start = m_probes[run.first];
        const Sample& end = m_probes[run.last];
        const std::size_t n = segmentsFor(run.length, m_c);
        if (n <= 1) {
            emitChord(start, end);
            return;
        }
        // Cumulative mapped length table over [start.u, end.u].
        m_tableU.clear();
        m_tableLength.clear();
        const std::uint32_t probeIntervals = run.last - run.first;
        bool refined = false;
        if (2 * n > probeIntervals) {
            const std::uint32_t tableSegments = std::uint32_t(
                std::min<std::size_t>(std::max<std::size_t>(2 * n, probeIntervals), kMaxLengthTableSegments));
            refined = true;
            Point3 previous = start.image;
            double total = 0.0;
            m_tableU.push_back(start.u);
            m_tableLength.push_back(0.0);
            for (std::uint32_t i = 1; i <= tableSegments && refined; ++i) {
                const double u = i == tableSegments
                                     ? end.u
                                     : start.u + (end.u - start.u) * (double(i) / double(tableSegments));
                const Sample sample = i == tableSegments ? end : makeSample(u);
                double step = 0.0;
                if (!sample.mapped || !std::isfinite(step = distance(previous, sample.image))) {
                    refined = false;
                    break;
                }
                total += step;
                previous = sample.image;
                m_tableU.push_back(u);
                m_tableLength.push_back(total);
            }
            if (!refined) {
                m_tableU.clear();
                m_tableLength.clear();
            }
        }
        if (!refined) {
            double total = 0.0;
            m_tableU.push_back(start.u);
            m_tableLength.push_back(0.0);
            for (std::uint32_t j = run.first + 1; j <= run.last; ++j) {
                total += distance(m_probes[j - 1].image, m_probes[j].image);
                m_tableU.push_back(m_probes[j].u);
                m_tableLength.push_back(total);
            }
        }

        const double total = m_tableLength.back();
        Sample previous = start;
        std::size_t index = 0;
        for (std::size_t i = 1; i < n; ++i) {
            double u;
            if (total > 0.0) {
                const double target = total * (double(i) / double(n));
                while (index + 2 < m_tableLength.size() && m_tableLength[index + 1] < target) {
                    ++index;
                }
                const double l0 = m_tableLength[index];
                const double l1 = m_tableLength[index + 1];
                const double f = l1 > l0 ? std::min(1.0, std::max(0.0, (target - l0) / (l1 - l0))) : 0.0;
                u = m_tableU[index] + (m_tableU[index + 1] - m_tableU[index]) * f;
            } else {
                u = start.u + (end.u - start.u) * (double(i) / double(n));
            }
            if (!(u > previous.u && u < end.u)) {
                continue;
            }
            const Sample sample = makeSample(u);
            emitChord(previous, sample);
            previous = sample;
        }
        emitChord(previous, end);
    }

    void emitRuns()
    {
        std::size_t cursor = 0;
        for (std::size_t s = 0; s < m_spans.count(); ++s) {
            m_currentSpan = s;
            probeSpan(s);
            for (; cursor < m_runs.size() && m_runs[cursor].span == s; ++cursor) {
                const Run& run = m_runs[cursor];
                if (run.measurable) {
                    emitMeasurableRun(run);
                } else {
                    for (std::uint32_t j = run.first; j < run.last; ++j) {
                        emitChord(m_probes[j], m_probes[j + 1]);
                    }
                }
            }
        }
        emit(m_probes[m_probeSegments]);
    }

    void emitOnePerSpan()
    {
        for (std::size_t s = 0; s < m_spans.count(); ++s) {
            m_currentSpan = s;
            m_points = m_spans.points(s);
            m_builder.add(m_spans.span(s).start, project(m_points[0]));
        }
        m_builder.add(m_spans.span(m_currentSpan).end, project(m_points[m_order - 1]));
    }

    Spans& m_spans;
    const PointMapping& m_mapping;
    TessellatedCurve& m_out;
    PolylineBuilder m_builder;
    const unsigned m_order;
    const std::uint32_t m_probeSegments;
    const BernsteinTable m_probeTable;
    std::vector<Sample> m_probes;
    const Point4* m_points = nullptr;
    std::size_t m_currentSpan = 0;

    std::vector<Run> m_runs;
    std::size_t m_measurableRuns = 0;
    std::size_t m_unmeasurableIntervals = 0;
    double m_totalLength = 0.0;

    double m_c = kInfinity;
    bool m_onePerSpan = false;
    std::size_t m_planned = 0;
    std::size_t m_extra = 0;

    // Right ends still to reach while bisecting one chord; depth counts the halvings
    // of the interval that ends there.
    struct Pending {
        Sample sample;
        unsigned depth;
    };
    std::vector<Pending> m_stack;
    std::vector<double> m_tableU;
    std::vector<double> m_tableLength;
};

} // namespace

TessellatedCurve tessellateConstant(const CurveRef& curve, std::uint32_t segmentsPerSpan)
{
    if (!validateCurve(curve).ok()) {
        return TessellatedCurve{};
    }
    CurveSpans spans(curve);
    return constantImpl(spans, segmentsPerSpan);
}

TessellatedCurve tessellateConstant(const BezierForm& form, std::uint32_t segmentsPerSpan)
{
    FormSpans spans(form);
    return constantImpl(spans, segmentsPerSpan);
}

TessellatedCurve tessellateAdaptive(const CurveRef& curve, double maxSegmentLength,
                                    const PointMapping& mapping)
{
    if (!validateCurve(curve).ok()) {
        return TessellatedCurve{};
    }
    if (countNonEmptySpans(curve) * curve.order <= kConvertOnceLimit) {
        return tessellateAdaptive(BezierForm(curve), maxSegmentLength, mapping);
    }
    TessellatedCurve out;
    CurveSpans spans(curve);
    Adaptive<CurveSpans>(spans, mapping, out).run(maxSegmentLength);
    return out;
}

TessellatedCurve tessellateAdaptive(const BezierForm& form, double maxSegmentLength,
                                    const PointMapping& mapping)
{
    TessellatedCurve out;
    FormSpans spans(form);
    Adaptive<FormSpans>(spans, mapping, out).run(maxSegmentLength);
    return out;
}

} // namespace q3::nurbs
