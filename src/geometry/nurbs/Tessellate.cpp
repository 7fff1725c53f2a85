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
// Adaptive: the fewest segments no longer than c1 come from marching along the curve
// and ending each segment as late as the length bound allows. Per span,
// probeSegmentsPerSpan probes are mapped first; they find where the mapping fails and
// estimate the mapped length L of each run of mappable curve (chord sums), which gives
// the planned count ceil(1.03 L / c1) and lets kMaxSegments be respected, by choosing
// a larger c1, before anything is emitted. The march then goes run by run: from the
// current vertex it scans a table of samples (the probes, or about two per planned
// segment) for the first one whose mapped chord exceeds c1, and closes in on the
// crossing inside that bracket with safeguarded regula falsi until the chord is within
// 3% below c1. Every chord is thus measured exactly between its mapped end points, so
// the bound holds by construction, and segments are normally at least 97% of c1, the
// last of each run excepted. Where the mapping fails, bisection finds the edge of the
// mapped part inside a probe interval (or both edges of a gap the march runs into), so
// the mapped part is measured up to its edge; the rest gets one unmeasured segment per
// probe interval, and a gap two.
// With a ProjectiveMapping (what views pass), a span whose control points all map in
// front of the eye (and beyond the hither plane) has an image everywhere, and that
// image is itself a rational Bezier curve with the mapped control points. Such a span
// is sampled with the constant method's kernel (about one sample per planned
// segment); the chords between the samples give its sampled length S (a lower bound
// of its length), and it gets ceil(S / (0.985 c1)) segments of equal sampled length,
// each vertex's parameter found by cubic Hermite interpolation of the parameter
// against sampled length. The vertices are then evaluated (one Horner pass gives the
// point and, through the map, its image) and every chord measured between the images
// of its ends; the rare span where one is longer than c1 (the samples missed a quick
// turn) is marched greedily from its start instead. Most vertices thus cost one
// evaluation and no root finding, and the work splits into loops without a chain of
// dependent divisions between vertices.
// This is chord-length parameterisation, not a formula from the article, which
// only defines what the methods promise ("CONTROLLING SUBDIVISION").

#include "geometry/nurbs/Tessellate.h"

#include "core/ThreadLocal.h"

#include "geometry/nurbs/Evaluate.h"
#include "geometry/nurbs/Knots.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

namespace q3::nurbs {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// Two doubles in one SSE2 register (GCC/Clang vector extension, as in Bezier.cpp); no
// fused multiply-add is enabled, so every lane rounds as the scalar code would.
typedef double Double2 __attribute__((vector_size(16)));

class FormSpans {
public:
    explicit FormSpans(const BezierForm& form) : m_form(form) {}
    std::size_t count() const { return m_form.spanCount(); }
    unsigned order() const { return m_form.order(); }
    const Span& span(std::size_t s) const { return m_form.span(s); }
    const Point4* points(std::size_t s) { return m_form.spanPoints(s); }
    Point4 startPoint(std::size_t s) { return m_form.spanPoints(s)[0]; }
    Point4 endPoint() { return m_form.spanPoints(count() - 1)[order() - 1]; }

private:
    const BezierForm& m_form;
};

class CurveSpans {
public:
    explicit CurveSpans(const CurveRef& curve) : m_curve(curve), m_spans(nonEmptySpans(curve)), m_sweep(curve) {}
    std::size_t count() const { return m_spans.size(); }
    unsigned order() const { return m_curve.order; }
    const Span& span(std::size_t s) const { return m_spans[s]; }
    const Point4* points(std::size_t s)
    {
        m_sweep.convert(m_spans[s].knotIndex, m_scratch);
        return m_scratch;
    }
    // The Bezier form's first point is de Boor's value at the span start (same
    // arithmetic), at half the cost of converting the span.
    Point4 startPoint(std::size_t s) { return evaluate(m_curve, m_spans[s].start).homogeneous; }
    Point4 endPoint() { return evaluate(m_curve, m_spans.back().end).homogeneous; }

private:
    CurveRef m_curve;
    std::vector<Span> m_spans;
    BezierSweep m_sweep;
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

// The same rule as PolylineBuilder, applied in place to vertices [from, to) that were
// written in bulk; `kept` vertices before `from` are final. Returns the new count.
std::size_t dropRepeats(float* v, double* t, std::size_t kept, std::size_t from, std::size_t to)
{
    for (std::size_t r = from; r < to; ++r) {
        if (kept > 0 && sameVertex(v + 3 * r, v + 3 * (kept - 1))) {
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
    return kept;
}

// What the options let one tessellation spend (TessellationOptions::maxSegments,
// the culling), as the two methods take it.
struct ViewLimits {
    std::size_t maxSegments = kMaxSegments;
    const SpanCulling& hidden;
};

// Clears a result's flags and counts; its arrays are left for the method to
// size (the constant method writes every element it keeps, so growing the
// arrays from their old size rather than from empty saves zeroing them: a
// view re-tessellates into one result every frame).
void resetReport(TessellatedCurve& out)
{
    out.substituted = false;
    out.effectiveValue = 0.0;
    out.capped = false;
    out.unmeasuredSegments = 0;
    out.hiddenSpans = 0;
}

// Empties a result but keeps its storage for reuse.
void reset(TessellatedCurve& out)
{
    out.vertices.clear();
    out.parameters.clear();
    resetReport(out);
}

std::size_t segmentCap(const ViewLimits& limits)
{
    return std::max<std::size_t>(std::min(limits.maxSegments, kMaxSegments), 1);
}

template <typename Spans>
void constantImpl(Spans& spans, double requested, TessellatedCurve& out, const ViewLimits& limits)
{
    resetReport(out);
    const std::size_t spanCount = spans.count();
    if (spanCount == 0) {
        out.vertices.clear();
        out.parameters.clear();
        return;
    }
    std::uint32_t m = clampedSegments(requested);
    // Hidden spans (one segment each) are found first, so the cap is shared by the
    // spans that can be seen. Culling needs each span's Bezier form, which one segment
    // per span does not: then nothing is culled.
    std::vector<bool> hidden;
    if (limits.hidden && m > 1) {
        hidden.resize(spanCount);
        for (std::size_t s = 0; s < spanCount; ++s) {
            hidden[s] = limits.hidden(spans.points(s), spans.order());
            out.hiddenSpans += hidden[s] ? 1 : 0;
        }
    }
    const std::size_t visibleSpans = spanCount - out.hiddenSpans;
    const std::size_t cap = segmentCap(limits);
    const std::size_t perSpanBudget =
        visibleSpans == 0 ? m : std::max<std::size_t>((cap > out.hiddenSpans ? cap - out.hiddenSpans : 0) / visibleSpans, 1);
    m = std::uint32_t(std::min<std::size_t>(m, perSpanBudget));
    out.substituted = double(m) != requested;
    out.effectiveValue = m;

    if (out.table.order() != spans.order() || out.table.segments() != m) {
        out.table = BernsteinTable(spans.order(), m);
    }
    const BernsteinTable& table = out.table;
    std::vector<double> fraction(m);
    for (std::uint32_t j = 0; j < m; ++j) {
        fraction[j] = double(j) / double(m);
    }
    const std::size_t vertexCount = spanCount * m + 1;
    out.vertices.resize(3 * vertexCount);
    out.parameters.resize(vertexCount);
    float* v = out.vertices.data();
    double* t = out.parameters.data();
    std::size_t kept = 0;
    if (m == 1) {
        // Only span starts: no need for whole Bezier forms.
        for (std::size_t s = 0; s < spanCount; ++s) {
            const Point3 p = project(spans.startPoint(s));
            v[3 * s] = float(p.x);
            v[3 * s + 1] = float(p.y);
            v[3 * s + 2] = float(p.z);
            t[s] = spans.span(s).start;
        }
        const Point3 p = project(spans.endPoint());
        v[3 * spanCount] = float(p.x);
        v[3 * spanCount + 1] = float(p.y);
        v[3 * spanCount + 2] = float(p.z);
        t[spanCount] = spans.span(spanCount - 1).end;
        kept = dropRepeats(v, t, 0, 0, vertexCount);
        out.vertices.resize(3 * kept);
        out.parameters.resize(kept);
        return;
    }
    // Each span is sampled just past the vertices kept so far and compacted while it is
    // still in cache.
    const Point4* points = nullptr;
    for (std::size_t s = 0; s < spanCount; ++s) {
        points = spans.points(s);
        const Span& span = spans.span(s);
        if (!hidden.empty() && hidden[s]) {
            const Point3 p = project(points[0]);
            v[3 * kept] = float(p.x);
            v[3 * kept + 1] = float(p.y);
            v[3 * kept + 2] = float(p.z);
            t[kept] = span.start;
            kept = dropRepeats(v, t, kept, kept, kept + 1);
            continue;
        }
        sampleBezier(points, table, 0, m, v + 3 * kept);
        const double width = span.end - span.start;
        for (std::uint32_t j = 0; j < m; ++j) {
            t[kept + j] = span.start + width * fraction[j];
        }
        kept = dropRepeats(v, t, kept, kept, kept + m);
    }
    sampleBezier(points, table, m, 1, v + 3 * kept);
    t[kept] = spans.span(spanCount - 1).end;
    kept = dropRepeats(v, t, kept, kept, kept + 1);
    out.vertices.resize(3 * kept);
    out.parameters.resize(kept);
}

struct Sample {
    double u = 0.0;
    Point3 point;
    Point3 image;
    bool mapped = false;
};

constexpr std::uint32_t kNoBoundary = std::numeric_limits<std::uint32_t>::max();

// A maximal stretch of one span that is all measurable (every point mapped, as far as
// the probes tell) or all not. It runs from probe `first` to probe `last`, except that
// an end inside a probe interval with one unmapped end is the boundary point found
// there (headBoundary / tailBoundary index the boundary samples). Its vertices before
// the tail are its head, then (measurable) the march's or (not measurable) the probes
// first+1 .. last-1; the tail is the next run's head.
struct Run {
    std::size_t span = 0;
    std::uint32_t first = 0;
    std::uint32_t last = 0;
    bool measurable = false;
    double length = 0.0;
    std::uint32_t headBoundary = kNoBoundary;
    std::uint32_t tailBoundary = kNoBoundary;
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
    Adaptive(Spans& spans, const PointMapping* mapping, const ProjectiveMapping* projective,
             const ViewLimits& limits, TessellatedCurve& out)
        : m_spans(spans), m_mapping(mapping), m_projective(projective), m_hidden(limits.hidden),
          m_maxSegments(segmentCap(limits)),
          m_budget(m_maxSegments - m_maxSegments / 8), m_out(out), m_builder(out), m_order(spans.order()),
          m_probeSegments(probeSegmentsPerSpan(m_order)), m_probeTable(m_order, m_probeSegments),
          m_probes(m_probeSegments + 1)
    {
        if (projective != nullptr) {
            // Rows scale * (row k) + offset * (row W), 0 for an axis with scale 0, so
            // that a homogeneous point's image is (row 0, row 1, row 2) / row 3.
            for (int k = 0; k < 3; ++k) {
                for (int c = 0; c < 4; ++c) {
                    const double scale = projective->scale[k];
                    m_imageMatrix[k][c] = scale == 0.0 ? 0.0
                                                       : scale * projective->matrix[k][c] +
                                                             projective->offset[k] * projective->matrix[3][c];
                }
            }
            for (int c = 0; c < 4; ++c) {
                m_imageMatrix[3][c] = projective->matrix[3][c];
                m_imageColumns[c][0] = Double2{m_imageMatrix[0][c], m_imageMatrix[1][c]};
                m_imageColumns[c][1] = Double2{m_imageMatrix[2][c], m_imageMatrix[3][c]};
            }
        }
        m_binomials[0] = 1.0;
        for (unsigned r = 1; r < m_order; ++r) {
            m_binomials[r] = m_binomials[r - 1] * double(m_order - r) / double(r);
        }
    }

    void run(double c1)
    {
        const std::size_t spanCount = m_spans.count();
        if (spanCount == 0) {
            return;
        }
        if (spanCount >= m_budget) {
            // At least one segment per span already exceeds the budget.
            m_out.substituted = true;
            m_onePerSpan = true;
            m_out.effectiveValue = kInfinity;
        } else {
            collectRuns();
            chooseLength(c1);
        }
        if (m_onePerSpan) {
            emitOnePerSpan();
        } else {
            emitRuns();
        }
    }

private:
    bool mapPoint(const Point3& p, Point3& image) const
    {
        if (m_projective != nullptr) {
            return (*m_projective)(p, image);
        }
        if (!(*m_mapping)(p, image)) {
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
        probePoints();
    }

    // Probes the span whose Bezier points m_points holds.
    void probePoints()
    {
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

    // The mapped point nearest (in u) to where the curve loses its image between a
    // mapped and an unmapped sample: bisection down to adjacent doubles, at most
    // kMaxRootIterations evaluations.
    Sample boundaryBetween(Sample mapped, Sample unmapped) const
    {
        for (unsigned iteration = 0; iteration < kMaxRootIterations; ++iteration) {
            const double u = 0.5 * (mapped.u + unmapped.u);
            if (u == mapped.u || u == unmapped.u) {
                break;
            }
            const Sample sample = makeSample(u);
            if (sample.mapped) {
                mapped = sample;
            } else {
                unmapped = sample;
            }
        }
        return mapped;
    }

    // Adds one probe interval's piece to the runs: from probe `first` (or boundary
    // `head`) to probe first+1 (or boundary `tail`), measurable or not, merged into the
    // previous run when that is of the same kind and ends where the piece starts.
    void addPiece(std::size_t s, std::uint32_t first, bool isMeasurable, double length,
                  std::uint32_t head, std::uint32_t tail)
    {
        if (!m_runs.empty()) {
            Run& previous = m_runs.back();
            if (previous.span == s && previous.measurable == isMeasurable && previous.last == first &&
                previous.tailBoundary == kNoBoundary && head == kNoBoundary) {
                previous.last = first + 1;
                previous.length += length;
                previous.tailBoundary = tail;
                if (isMeasurable) {
                    m_totalLength += length;
                } else {
                    ++m_unmeasurableIntervals;
                }
                return;
            }
        }
        Run run;
        run.span = s;
        run.first = first;
        run.last = first + 1;
        run.measurable = isMeasurable;
        run.length = length;
        run.headBoundary = head;
        run.tailBoundary = tail;
        if (isMeasurable) {
            ++m_measurableRuns;
            m_totalLength += length;
        } else {
            ++m_unmeasurableIntervals;
        }
        m_runs.push_back(run);
    }

    // Probe intervals with both ends mapped are measurable; one with a single mapped
    // end is split at the boundary point, so the visible side is measured up to where
    // the image ends (the hither plane, for a screen-space mapping) and only the side
    // without an image is an unmeasured segment.
    void collectRuns()
    {
        if (m_hidden) {
            m_spanHidden.assign(m_spans.count(), false);
        }
        if (m_projective != nullptr) {
            m_spanMapped.assign(m_spans.count(), false);
        }
        m_runs.reserve(m_spans.count());
        for (std::size_t s = 0; s < m_spans.count(); ++s) {
            m_points = m_spans.points(s);
            if (m_hidden && m_hidden(m_points, m_order)) {
                // One unmeasured segment across the span, no run.
                m_spanHidden[s] = true;
                ++m_out.hiddenSpans;
                ++m_unmeasurableIntervals;
                continue;
            }
            double length = 0.0;
            if (m_projective != nullptr && mapSpan() && measureMappedSpan(length)) {
                // The whole span has an image: one measurable run from its first probe
                // to its last, measured on the mapped span's probes.
                m_spanMapped[s] = true;
                Run run;
                run.span = s;
                run.first = 0;
                run.last = m_probeSegments;
                run.measurable = true;
                run.length = length;
                ++m_measurableRuns;
                m_totalLength += length;
                m_runs.push_back(run);
                continue;
            }
            probePoints();
            for (std::uint32_t j = 0; j < m_probeSegments; ++j) {
                const Sample& a = m_probes[j];
                const Sample& b = m_probes[j + 1];
                double length = 0.0;
                if (measurable(a, b, length)) {
                    addPiece(s, j, true, length, kNoBoundary, kNoBoundary);
                } else if (a.mapped != b.mapped && m_edgeSearches < kMaxEdgeSearches) {
                    ++m_edgeSearches;
                    const std::uint32_t index = std::uint32_t(m_boundaries.size());
                    m_boundaries.push_back(a.mapped ? boundaryBetween(a, b) : boundaryBetween(b, a));
                    const Sample& edge = m_boundaries.back();
                    if (a.mapped) {
                        addPiece(s, j, true, distance(a.image, edge.image), kNoBoundary, index);
                        addPiece(s, j, false, 0.0, index, kNoBoundary);
                    } else {
                        addPiece(s, j, false, 0.0, kNoBoundary, index);
                        addPiece(s, j, true, distance(edge.image, b.image), index, kNoBoundary);
                    }
                } else {
                    addPiece(s, j, false, 0.0, kNoBoundary, kNoBoundary);
                }
            }
        }
    }

    const Sample& head(const Run& run) const
    {
        return run.headBoundary == kNoBoundary ? m_probes[run.first] : m_boundaries[run.headBoundary];
    }

    const Sample& tail(const Run& run) const
    {
        return run.tailBoundary == kNoBoundary ? m_probes[run.last] : m_boundaries[run.tailBoundary];
    }

    static std::size_t segmentsFor(double length, double c)
    {
        if (!(length > 0.0) || c == kInfinity) {
            return 1;
        }
        const double q = std::ceil(length * kLengthPadding / c);
        if (!(q < double(kMaxSegments))) {
            return kMaxSegments + 1;  // over any budget
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

    void setLength(double c)
    {
        m_c = c;
        m_c2 = c * c * (1.0 - 1e-12);
        m_target = (1.0 - 0.5 * kChordTolerance) * c;
        m_out.effectiveValue = c;
    }

    void chooseLength(double c1)
    {
        const bool usable = c1 > 0.0;
        if (usable) {
            if (wanted(c1) <= m_budget) {
                setLength(c1);
                return;
            }
        }
        m_out.substituted = true;
        const std::size_t fixed = m_unmeasurableIntervals + m_measurableRuns;
        if (fixed >= m_budget) {
            m_onePerSpan = true;
            m_c = kInfinity;
            m_out.effectiveValue = kInfinity;
            return;
        }
        // Each run needs at most padding * length / c + 1 segments, so this c fits.
        const std::size_t room = m_budget - fixed;
        double c = m_totalLength > 0.0 ? m_totalLength * kLengthPadding / double(room) : kInfinity;
        if (!(c > 0.0)) {
            c = kInfinity;
        }
        for (int attempt = 0; attempt < 64 && wanted(c) > m_budget; ++attempt) {
            c *= 1.0 + 1.0 / 1024.0;
        }
        setLength(c);
    }

    // Appends the vertex that starts the next chord.
    void emit(const Sample& sample)
    {
        m_builder.add(spanParameter(m_spans.span(m_currentSpan), sample.u), sample.point);
        ++m_used;
    }

    // Room for `count` more chords besides the final chord of the current run and the
    // minimum every later run still needs.
    bool haveRoom(std::size_t count) const
    {
        return m_used + count + 1 + m_reserve <= m_maxSegments;
    }

    // Chord length between mapped points; infinity when it cannot be measured.
    double chord(const Sample& a, const Sample& b) const
    {
        if (!a.mapped || !b.mapped) {
            return kInfinity;
        }
        const double d = distance(a.image, b.image);
        return std::isfinite(d) ? d : kInfinity;
    }

    // The samples a run's chords are bracketed with: the run's probes, or ~2n samples
    // uniform in u when the run needs more segments than half its probes.
    void buildTable(const Run& run, std::size_t n)
    {
        m_table.clear();
        const std::uint32_t probeIntervals = run.last - run.first;
        if (2 * n > probeIntervals) {
            const std::uint32_t segments = std::uint32_t(
                std::min<std::size_t>(std::max<std::size_t>(2 * n, probeIntervals), kMaxLengthTableSegments));
            const double u0 = head(run).u;
            const double u1 = tail(run).u;
            m_table.push_back(head(run));
            for (std::uint32_t i = 1; i < segments; ++i) {
                m_table.push_back(makeSample(u0 + (u1 - u0) * (double(i) / double(segments))));
                if (!m_table.back().mapped) {
                    m_table.clear();
                    break;
                }
            }
            if (!m_table.empty()) {
                m_table.push_back(tail(run));
                return;
            }
        }
        m_table.push_back(head(run));
        m_table.insert(m_table.end(), m_probes.begin() + run.first + 1, m_probes.begin() + run.last);
        m_table.push_back(tail(run));
    }

    // Searches (lo, hi) for a point whose chord from `from` is within
    // [(1 - kChordTolerance) c, c], given chord(from, lo) <= c < chord(from, hi). Returns
    // the best lo found; sets `unmappable` instead when it meets a point with no image,
    // returns that point and leaves the bracket's mapped end in `lastMapped`.
    Sample findCrossing(const Sample& from, Sample lo, Sample hi, bool& unmappable, Sample& lastMapped) const
    {
        unmappable = false;
        double dlo = chord(from, lo);
        double dhi = chord(from, hi);
        const double accept = (1.0 - kChordTolerance) * m_c;
        const double target = (1.0 - 0.5 * kChordTolerance) * m_c;
        for (unsigned iteration = 0; iteration < kMaxRootIterations && dlo < accept; ++iteration) {
            double f = 0.5;
            if (iteration % 3 != 2 && std::isfinite(dhi)) {
                f = std::min(0.95, std::max(0.05, (target - dlo) / (dhi - dlo)));
            }
            const double u = lo.u + (hi.u - lo.u) * f;
            if (!(lo.u < u && u < hi.u)) {
                break;
            }
            const Sample sample = makeSample(u);
            if (!sample.mapped) {
                unmappable = true;
                lastMapped = lo;
                return sample;
            }
            const double d = chord(from, sample);
            if (d <= m_c) {
                lo = sample;
                dlo = d;
            } else {
                hi = sample;
                dhi = d;
            }
        }
        return lo.u > from.u ? lo : hi;
    }

    // Greedy march along a measurable run: from each vertex, the next is the point
    // where the mapped chord reaches (1 - kChordTolerance) c to c, found by scanning the
    // table for the first sample farther than c and closing in on the crossing.
    void emitMeasurableRun(const Run& run)
    {
        buildTable(run, segmentsFor(run.length, m_c));
        std::size_t last = m_table.size() - 1;
        Sample current = m_table.front();
        std::size_t index = 0;  // largest table index with u <= current.u
        unsigned gaps = 0;
        for (;;) {
            std::size_t j = index + 1;
            while (j <= last && m_table[j].mapped && chord(current, m_table[j]) <= m_c) {
                ++j;
            }
            if (j > last) {
                break;
            }
            if (!haveRoom(m_table[j].mapped ? 2 : 3)) {
                m_out.capped = true;
                break;
            }
            if (!m_table[j].mapped) {
                // A gap: a chord to its near edge (within c, or current is that edge),
                // then two unmeasured chords through the point without an image to its
                // far edge. They run through the part that is not drawn (a chord
                // straight from edge to edge could cut across the image).
                emit(current);
                if (m_table[j - 1].u > current.u) {
                    emit(m_table[j - 1]);
                }
                emit(m_table[j]);
                m_out.unmeasuredSegments += 2;
                current = m_table[j + 1];
                index = j + 1;
                continue;
            }
            const Sample lo = m_table[j - 1].u > current.u ? m_table[j - 1] : current;
            bool unmappable = false;
            Sample lastMapped;
            const Sample next = findCrossing(current, lo, m_table[j], unmappable, lastMapped);
            if (unmappable && gaps < kMaxGapsPerRun && m_edgeSearches + 2 <= kMaxEdgeSearches) {
                m_edgeSearches += 2;
                // The curve loses its image between lastMapped and table sample j: put
                // both edges of the gap and the point without an image between them in
                // the table, so the march measures up to the near edge and resumes
                // from the far one.
                ++gaps;
                Sample edges[4];
                std::size_t count = 0;
                if (lastMapped.u > m_table[j - 1].u) {
                    edges[count++] = lastMapped;
                }
                const Sample nearEdge = boundaryBetween(lastMapped, next);
                if (nearEdge.u > lastMapped.u) {
                    edges[count++] = nearEdge;
                }
                edges[count++] = next;
                const Sample farEdge = boundaryBetween(m_table[j], next);
                if (farEdge.u < m_table[j].u) {
                    edges[count++] = farEdge;
                }
                m_table.insert(m_table.begin() + std::ptrdiff_t(j), edges, edges + count);
                last = m_table.size() - 1;
                continue;
            }
            emit(current);
            if (unmappable) {
                // Past kMaxGapsPerRun or kMaxEdgeSearches: two unmeasured chords to
                // table sample j.
                emit(next);
                m_out.unmeasuredSegments += 2;
                current = m_table[j];
                index = j;
                continue;
            }
            if (chord(current, next) > m_c) {
                m_out.capped = true;
            }
            current = next;
            while (index < last && m_table[index + 1].u <= current.u) {
                ++index;
            }
        }
        emit(current);
        if (chord(current, m_table[last]) > m_c) {
            m_out.capped = true;
        }
    }

    // Maps the control points of the span in m_points through m_projective into
    // m_imagePoints. Returns whether the whole span has an image: every mapped control
    // point has W > 0 (and Z < 0 with clipNearer), so every point of the span, a
    // positive combination of them, has too. The scale and offset are folded into the
    // homogeneous points ((scale X + offset W, ..., W) projects to scale X / W + offset),
    // so the span's image is the rational Bezier curve of m_imagePoints; an axis with
    // scale 0 maps to 0 rather than to its offset, which changes no distance.
    bool mapSpan()
    {
        const bool clipNearer = m_projective->clipNearer;
        const double* depth = m_projective->matrix[2];
        bool inside = true;
        for (unsigned i = 0; i < m_order; ++i) {
            const Point4& p = m_points[i];
            double v[4];
            for (int r = 0; r < 4; ++r) {
                const double* a = m_imageMatrix[r];
                v[r] = a[0] * p.x + a[1] * p.y + a[2] * p.z + a[3] * p.w;
            }
            const bool nearer =
                clipNearer && !(depth[0] * p.x + depth[1] * p.y + depth[2] * p.z + depth[3] * p.w < 0.0);
            inside = inside && v[3] > 0.0 && !nearer && std::isfinite(v[0]) && std::isfinite(v[1]) &&
                     std::isfinite(v[2]) && std::isfinite(v[3]);
            m_imagePoints[i] = Point4{v[0], v[1], v[2], v[3]};
        }
        return inside;
    }

    // The length of the mapped span's probe polygon (its images at the probes, from
    // m_imagePoints). Returns false when a probe's image is not finite.
    bool measureMappedSpan(double& length) const
    {
        double xyz[3 * (kMaxOrder + 1)];
        sampleBezier(m_imagePoints, m_probeTable, 0, m_probeSegments + 1, xyz);
        length = 0.0;
        for (std::uint32_t j = 0; j <= m_probeSegments; ++j) {
            const double* at = xyz + 3 * j;
            if (!(std::isfinite(at[0]) && std::isfinite(at[1]) && std::isfinite(at[2]))) {
                return false;
            }
            if (j > 0) {
                const double dx = at[0] - at[-3];
                const double dy = at[1] - at[-2];
                const double dz = at[2] - at[-1];
                length += std::sqrt(dx * dx + dy * dy + dz * dz);
            }
        }
        return true;
    }

    // Dense samples for a run of n planned segments: kDenseSamplesPerSegment each, from a
    // short ladder of sizes (8, 12, 16, 24, ...) so a few Bernstein tables serve a
    // whole curve; 0 past kMaxDenseSamples.
    static std::uint32_t denseCount(std::size_t n)
    {
        const std::size_t want = kDenseSamplesPerSegment * n;
        std::uint32_t d = 8;
        while (d < want) {
            if (d > kMaxDenseSamples) {
                return 0;
            }
            d = (d & (d - 1)) == 0 ? d + d / 2 : d / 3 * 4;
        }
        return d <= kMaxDenseSamples ? d : 0;
    }

    // The table for `samples` dense samples (a size from denseCount's ladder). Tables
    // are kept per thread across calls, so a renderer that tessellates every frame
    // builds each once: at most one per order and ladder size (about 1.8 MB in all
    // for order 16, as every size up to kMaxDenseSamples sums to about 14,000 rows).
    const BernsteinTable& denseTable(std::uint32_t samples) const
    {
        struct TablesTag;
        auto& tables = threadLocal<std::vector<std::unique_ptr<BernsteinTable>>, TablesTag>();
        unsigned rung = 0;
        for (std::uint32_t d = 8; d < samples; d = (d & (d - 1)) == 0 ? d + d / 2 : d / 3 * 4) {
            ++rung;
        }
        const std::size_t slot = std::size_t(m_order) * 32 + rung;
        if (tables.size() <= slot) {
            tables.resize(slot + 1);
        }
        if (!tables[slot]) {
            tables[slot] = std::make_unique<BernsteinTable>(m_order, samples);
        }
        return *tables[slot];
    }

    // The image of the mapped span at u: m_imagePoints' rational Bezier curve, by the
    // Horner scheme of evaluateBezier without its common factor (it cancels in the
    // division).
    Point3 imageAt(double u) const
    {
        const unsigned deg = m_order - 1;
        const Point4* q = m_imagePoints;
        double x;
        double y;
        double z;
        double w;
        if (u <= 0.5) {
            const double s = u / (1.0 - u);
            x = q[deg].x;
            y = q[deg].y;
            z = q[deg].z;
            w = q[deg].w;
            const double* binomial = m_binomials;
            for (unsigned r = deg; r-- > 0;) {
                x = x * s + binomial[r] * q[r].x;
                y = y * s + binomial[r] * q[r].y;
                z = z * s + binomial[r] * q[r].z;
                w = w * s + binomial[r] * q[r].w;
            }
        } else {
            const double s = (1.0 - u) / u;
            x = q[0].x;
            y = q[0].y;
            z = q[0].z;
            w = q[0].w;
            const double* binomial = m_binomials;
            for (unsigned r = 1; r <= deg; ++r) {
                x = x * s + binomial[r] * q[r].x;
                y = y * s + binomial[r] * q[r].y;
                z = z * s + binomial[r] * q[r].z;
                w = w * s + binomial[r] * q[r].w;
            }
        }
        return Point3{x / w, y / w, z / w};
    }

    static double distanceTo(const Point3& a, const double* b)
    {
        const double dx = b[0] - a.x;
        const double dy = b[1] - a.y;
        const double dz = b[2] - a.z;
        return std::sqrt(dx * dx + dy * dy + dz * dz);
    }

    // Whether the chord from a to b is at most m_c, decided as chord() decides it.
    bool within(const Point3& a, const double* b) const
    {
        const double dx = b[0] - a.x;
        const double dy = b[1] - a.y;
        const double dz = b[2] - a.z;
        const double d2 = dx * dx + dy * dy + dz * dz;
        return d2 <= m_c2 || std::sqrt(d2) <= m_c;
    }

    // Appends the vertex at local parameter u of the current span (its curve point
    // evaluated from m_points) as the start of the next chord.
    void emitAt(double u)
    {
        const Point3 p = u <= 0.0 ? project(m_points[0]) : project(evaluateBezier(m_points, m_order, u));
        m_builder.add(spanParameter(m_spans.span(m_currentSpan), u), p);
        ++m_used;
    }

    // The image of a homogeneous curve point: m_imageMatrix applied, then divided by
    // its W (the same map as mapSpan's, point by point).
    Point3 imageOf(const Point4& h) const
    {
        double v[4];
        for (int r = 0; r < 4; ++r) {
            const double* a = m_imageMatrix[r];
            v[r] = a[0] * h.x + a[1] * h.y + a[2] * h.z + a[3] * h.w;
        }
        return Point3{v[0] / v[3], v[1] / v[3], v[2] / v[3]};
    }

    // m_scaledPoints for the span in m_points: each point times its binomial
    // coefficient, so that Horner's rule needs one multiply-add per point.
    void scalePoints()
    {
        for (unsigned r = 0; r < m_order; ++r) {
            const Point4& p = m_points[r];
            const double c = m_binomials[r];
            m_scaledPoints[r][0] = Double2{c * p.x, c * p.y};
            m_scaledPoints[r][1] = Double2{c * p.z, c * p.w};
        }
    }

    // The curve point at local parameter u in (0, 1) of the span (m_scaledPoints set)
    // and its image: the Bernstein sum by Horner's rule in s = u / (1 - u) (or
    // (1 - u) / u past the midpoint, so s <= 1), which is the homogeneous point
    // divided by (1 - u)^deg (or u^deg), a positive factor that both projections
    // cancel.
    void pointAndImage(double u, Point3& point, Point3& image) const
    {
        const unsigned deg = m_order - 1;
        Double2 xy;
        Double2 zw;
        if (u <= 0.5) {
            const double sv = u / (1.0 - u);
            const Double2 s = {sv, sv};
            xy = m_scaledPoints[deg][0];
            zw = m_scaledPoints[deg][1];
            for (unsigned r = deg; r-- > 0;) {
                xy = xy * s + m_scaledPoints[r][0];
                zw = zw * s + m_scaledPoints[r][1];
            }
        } else {
            const double sv = (1.0 - u) / u;
            const Double2 s = {sv, sv};
            xy = m_scaledPoints[0][0];
            zw = m_scaledPoints[0][1];
            for (unsigned r = 1; r <= deg; ++r) {
                xy = xy * s + m_scaledPoints[r][0];
                zw = zw * s + m_scaledPoints[r][1];
            }
        }
        const Double2 x = {xy[0], xy[0]};
        const Double2 y = {xy[1], xy[1]};
        const Double2 z = {zw[0], zw[0]};
        const Double2 w = {zw[1], zw[1]};
        const Double2 v01 = m_imageColumns[0][0] * x + m_imageColumns[1][0] * y + m_imageColumns[2][0] * z +
                            m_imageColumns[3][0] * w;
        const Double2 v23 = m_imageColumns[0][1] * x + m_imageColumns[1][1] * y + m_imageColumns[2][1] * z +
                            m_imageColumns[3][1] * w;
        const Double2 one = {1.0, 1.0};
        const Double2 ws = {zw[1], v23[1]};
        const Double2 inv = one / ws;
        point = Point3{xy[0] * inv[0], xy[1] * inv[0], zw[0] * inv[0]};
        image = Point3{v01[0] * inv[1], v01[1] * inv[1], v23[0] * inv[1]};
    }

    // Span with an image everywhere (m_points and m_imagePoints set). Its image is a
    // rational Bezier curve of its own (m_imagePoints), which the kernel samples
    // directly, kDenseSamplesPerSegment per planned segment. The chords between
    // consecutive samples give the span's sampled length S, and the span gets the
    // fewest segments of at most kArcTarget * m_c of it, n = ceil(S / (kArcTarget
    // m_c)), equal in sampled length: vertex k sits where the sampled length reaches
    // k S / n (inverseLength). The vertices are then evaluated on the curve (each in
    // one go: the homogeneous point, its projection and its image) and every chord is
    // measured between the images of its two ends. The chord is at most the arc between
    // its ends, which the samples make about S / n, so the chords are normally just
    // below m_c; if one is not, the span is marched from its start one vertex at a time
    // instead (marchMapped). Spans that would need more than kMaxDenseSamples samples
    // take the general march.
    void emitMappedRun(const Run& run)
    {
        const std::uint32_t samples = denseCount(segmentsFor(run.length, m_c));
        if (samples == 0) {
            probePoints();
            emitMeasurableRun(run);
            return;
        }
        const BernsteinTable& table = denseTable(samples);
        const std::size_t count = std::size_t(samples) + 1;
        if (m_dense.size() < 5 * count) {
            m_dense.resize(5 * count);
        }
        double* image = m_dense.data();
        double* sampled = image + 3 * count;  // sampled length from u = 0 to each sample
        double* inverse = sampled + count;    // 1 / the length of each sample interval (0 for none)
        sampleBezier(m_imagePoints, table, 0, samples + 1, image);
        const double step = 1.0 / double(samples);
        for (std::size_t j = 0; j < samples; ++j) {
            const double* a = image + 3 * j;
            const double dx = a[3] - a[0];
            const double dy = a[4] - a[1];
            const double dz = a[5] - a[2];
            inverse[j] = std::sqrt(dx * dx + dy * dy + dz * dz);
        }
        sampled[0] = 0.0;
        for (std::size_t j = 0; j < samples; ++j) {
            sampled[j + 1] = sampled[j] + inverse[j];
        }
        for (std::size_t j = 0; j < samples; ++j) {
            inverse[j] = inverse[j] > 0.0 ? 1.0 / inverse[j] : 0.0;
        }
        const double total = sampled[samples];
        const double segments = std::ceil(total / (kArcTarget * m_c));
        emitAt(0.0);
        if (!(total < kInfinity) || !(segments < double(kMaxDenseSamples)) || !haveRoom(std::size_t(segments) + 1)) {
            marchMapped(0.0, Point3{image[0], image[1], image[2]}, 0, samples, step);
            return;
        }
        const std::uint32_t n = std::max<std::uint32_t>(std::uint32_t(segments), 1);
        const double spacing = total / double(n);
        const Point3 start = imageOf(m_points[0]);
        // From the first chord found longer than m_c on, the placement cannot be
        // trusted (the samples missed how the image moves): the span is marched from
        // its start one vertex at a time instead.
        const auto march = [&] { marchMapped(0.0, start, 0, samples, step); };
        // Vertex k (1 .. n - 1) in three passes, each free of the others' latency:
        // its parameter, its point and image, its chord from vertex k - 1.
        if (m_batchU.size() < std::size_t(n) + 1) {
            m_batchU.resize(std::size_t(n) + 1);
            m_batchPoints.resize(std::size_t(n) + 1);
            m_batchImages.resize(std::size_t(n) + 1);
        }
        double* u = m_batchU.data();
        Point3* points = m_batchPoints.data();
        Point3* images = m_batchImages.data();
        u[0] = 0.0;
        std::uint32_t j = 1;
        for (std::uint32_t k = 1; k < n; ++k) {
            // sampled[j - 1] < target <= sampled[j] (up to rounding at the end, which
            // the test of u[k] catches).
            const double target = spacing * double(k);
            while (j < samples && sampled[j] < target) {
                ++j;
            }
            u[k] = inverseLength(sampled, inverse, samples, j, target) * step;
            if (!(u[k] > u[k - 1] && u[k] < 1.0)) {
                march();
                return;
            }
        }
        scalePoints();
        for (std::uint32_t k = 1; k < n; ++k) {
            pointAndImage(u[k], points[k], images[k]);
        }
        images[0] = start;
        images[n] = imageOf(m_points[m_order - 1]);
        for (std::uint32_t k = 1; k <= n; ++k) {
            const double dx = images[k].x - images[k - 1].x;
            const double dy = images[k].y - images[k - 1].y;
            const double dz = images[k].z - images[k - 1].z;
            const double d2 = dx * dx + dy * dy + dz * dz;
            if (!(d2 <= m_c2 || std::sqrt(d2) <= m_c)) {
                march();
                return;
            }
        }
        // The interior vertices go straight into the output, as PolylineBuilder would
        // add them (one equal to its predecessor in float is dropped, its parameter
        // kept).
        const Span& span = m_spans.span(m_currentSpan);
        const double width = span.end - span.start;
        std::size_t kept = m_out.parameters.size();
        m_out.vertices.resize(3 * (kept + n - 1));
        m_out.parameters.resize(kept + n - 1);
        float* vertices = m_out.vertices.data();
        double* parameters = m_out.parameters.data();
        for (std::uint32_t k = 1; k < n; ++k) {
            const float vertex[3] = {float(points[k].x), float(points[k].y), float(points[k].z)};
            const double parameter = span.start + width * u[k];
            if (kept > 0 && sameVertex(vertex, vertices + 3 * (kept - 1))) {
                if (kept > 1) {
                    parameters[kept - 1] = parameter;
                }
                continue;
            }
            vertices[3 * kept] = vertex[0];
            vertices[3 * kept + 1] = vertex[1];
            vertices[3 * kept + 2] = vertex[2];
            parameters[kept] = parameter;
            ++kept;
        }
        m_out.vertices.resize(3 * kept);
        m_out.parameters.resize(kept);
        m_used += n - 1;
    }

    // Where (in samples, j - 1 + fraction) the sampled length reaches `target`, given
    // sampled[j - 1] < target <= sampled[j] and the reciprocal interval lengths:
    // cubic Hermite interpolation of the sample index as a function of length, with
    // slopes at the two samples averaged from the intervals beside each, which follows
    // a speed that changes along the interval far better than a straight line.
    static double inverseLength(const double* sampled, const double* inverse, std::uint32_t samples,
                                std::uint32_t j, double target)
    {
        const double a = sampled[j - 1];
        const double length = sampled[j] - a;
        const double t = (target - a) * inverse[j - 1];
        // Slopes d(index)/d(length) times `length`: 1 where the speed is uniform.
        const double m0 = j >= 2 ? std::min(3.0, 0.5 + 0.5 * length * inverse[j - 2]) : 1.0;
        const double m1 = j < samples ? std::min(3.0, 0.5 + 0.5 * length * inverse[j]) : 1.0;
        const double t2 = t * t;
        const double t3 = t2 * t;
        const double fraction = (t3 - 2.0 * t2 + t) * m0 + (3.0 * t2 - 2.0 * t3) + (t3 - t2) * m1;
        return double(j - 1) + fraction;
    }

    // The one-vertex-at-a-time march of a mapped span from the vertex at u (image
    // `from`, already emitted; `index` the last of the `samples` dense samples in
    // m_dense at or before u): from the current vertex it scans for the first sample
    // farther than m_c, then closes in between the sample before it (or the current
    // vertex when that sample is not past it) and that one with safeguarded regula
    // falsi on the chord length, each step evaluating the image polynomials at one
    // parameter, until the chord lies in [(1 - kChordTolerance) m_c, m_c].
    void marchMapped(double u, Point3 from, std::uint32_t index, std::uint32_t samples, double step)
    {
        const double* image = m_dense.data();
        const double accept = (1.0 - kChordTolerance) * m_c;
        for (;;) {
            std::uint32_t j = index + 1;
            while (j <= samples && within(from, image + 3 * std::size_t(j))) {
                ++j;
            }
            if (j > samples) {
                break;
            }
            if (!haveRoom(2)) {
                m_out.capped = true;
                break;
            }
            // The chord's end lies in (lo, hi]: lo within m_c (sample j - 1, or the
            // current vertex when that sample is not past it), hi sample j beyond it.
            double lo = u;
            Point3 loImage = from;
            double dlo = 0.0;
            if (j - 1 > index) {
                const double* at = image + 3 * std::size_t(j - 1);
                lo = double(j - 1) * step;
                loImage = Point3{at[0], at[1], at[2]};
                dlo = distanceTo(from, at);
            }
            double hi = double(j) * step;
            double dhi = distanceTo(from, image + 3 * std::size_t(j));
            for (unsigned iteration = 0; iteration < kMaxRootIterations && dlo < accept; ++iteration) {
                double f = 0.5;
                if (iteration % 3 != 2 && std::isfinite(dhi)) {
                    f = std::min(0.95, std::max(0.05, (m_target - dlo) / (dhi - dlo)));
                }
                const double um = lo + (hi - lo) * f;
                if (!(lo < um && um < hi)) {
                    break;
                }
                const Point3 im = imageAt(um);
                const double d = distance(from, im);
                if (d <= m_c) {
                    lo = um;
                    loImage = im;
                    dlo = d;
                } else {
                    hi = um;
                    dhi = std::isfinite(d) ? d : kInfinity;
                }
            }
            if (!(lo > u)) {
                m_out.capped = true;
                break;
            }
            u = lo;
            from = loImage;
            index = j - 1;
            emitAt(u);
        }
    }

    void emitRuns()
    {
        m_reserve = m_measurableRuns + m_unmeasurableIntervals;
        std::size_t cursor = 0;
        Point3 end;
        for (std::size_t s = 0; s < m_spans.count(); ++s) {
            m_currentSpan = s;
            if (!m_spanHidden.empty() && m_spanHidden[s]) {
                m_points = m_spans.points(s);
                Sample start;
                start.point = project(m_points[0]);
                m_reserve -= 1;
                emit(start);
                ++m_out.unmeasuredSegments;
                end = project(m_points[m_order - 1]);
                continue;
            }
            if (!m_spanMapped.empty() && m_spanMapped[s]) {
                m_points = m_spans.points(s);
                mapSpan();
                for (; cursor < m_runs.size() && m_runs[cursor].span == s; ++cursor) {
                    m_reserve -= 1;
                    emitMappedRun(m_runs[cursor]);
                }
                end = project(m_points[m_order - 1]);
                continue;
            }
            probeSpan(s);
            end = m_probes[m_probeSegments].point;
            for (; cursor < m_runs.size() && m_runs[cursor].span == s; ++cursor) {
                const Run& run = m_runs[cursor];
                if (run.measurable) {
                    m_reserve -= 1;
                    emitMeasurableRun(run);
                } else {
                    m_reserve -= run.last - run.first;
                    emit(head(run));
                    for (std::uint32_t j = run.first + 1; j < run.last; ++j) {
                        emit(m_probes[j]);
                    }
                    m_out.unmeasuredSegments += run.last - run.first;
                }
            }
        }
        m_builder.add(m_spans.span(m_currentSpan).end, end);
    }

    void emitOnePerSpan()
    {
        for (std::size_t s = 0; s < m_spans.count(); ++s) {
            m_builder.add(m_spans.span(s).start, project(m_spans.startPoint(s)));
        }
        m_builder.add(m_spans.span(m_spans.count() - 1).end, project(m_spans.endPoint()));
    }

    Spans& m_spans;
    const PointMapping* m_mapping;
    const ProjectiveMapping* m_projective;  // when given, used instead of m_mapping
    const SpanCulling& m_hidden;
    const std::size_t m_maxSegments;  // ViewLimits::maxSegments, at most kMaxSegments
    const std::size_t m_budget;       // the planned count's share of it (kPlacementBudget's rule)
    TessellatedCurve& m_out;
    PolylineBuilder m_builder;
    const unsigned m_order;
    const std::uint32_t m_probeSegments;
    const BernsteinTable m_probeTable;
    std::vector<Sample> m_probes;
    const Point4* m_points = nullptr;
    std::size_t m_currentSpan = 0;

    std::vector<Run> m_runs;
    std::vector<bool> m_spanHidden;  // empty without culling
    std::vector<bool> m_spanMapped;  // spans with an image everywhere; empty without m_projective
    Point4 m_imagePoints[kMaxOrder];  // the current span's image as a rational Bezier curve (mapSpan)
    double m_binomials[kMaxOrder] = {};  // binomial coefficients of degree m_order - 1
    double m_imageMatrix[4][4] = {};     // m_projective with its scale and offset folded in
    Double2 m_imageColumns[4][2] = {};   // m_imageMatrix by columns, rows (0, 1) and (2, 3)
    Double2 m_scaledPoints[kMaxOrder][2] = {};  // the span's points times binomials, (x, y) and (z, w)
    std::vector<double> m_dense;     // images of a mapped span's dense samples, their sampled lengths
    std::vector<double> m_batchU;    // a mapped span's vertices: parameters, points and images
    std::vector<Point3> m_batchPoints;
    std::vector<Point3> m_batchImages;
    std::vector<Sample> m_boundaries;  // where the image ends inside a probe interval
    std::size_t m_edgeSearches = 0;    // boundaryBetween calls so far, up to kMaxEdgeSearches
    std::size_t m_measurableRuns = 0;
    std::size_t m_unmeasurableIntervals = 0;
    double m_totalLength = 0.0;

    double m_c = kInfinity;
    double m_c2 = kInfinity;  // m_c squared, rounded down: below it a chord is within m_c
    double m_target = kInfinity;  // where a dense march aims a segment end
    bool m_onePerSpan = false;
    std::size_t m_used = 0;     // chords started so far
    std::size_t m_reserve = 0;  // chords the runs not yet started need at least
    std::vector<Sample> m_table;
};

// Most Bezier points a thread keeps in its form between calls (1 MB); a larger form is
// freed after use.
constexpr std::size_t kKeptFormPoints = std::size_t{1} << 15;

// Calls use(form) with the Bezier form of a valid curve that fits kWholeFormLimit,
// built in storage the thread keeps between calls, so that a curve tessellated every
// frame does not allocate (and fault in) its form every time. A call made while the
// storage is in use (a mapping or culling callback that tessellates) gets a form of
// its own.
template <typename Use>
void withWholeForm(const CurveRef& curve, const Use& use)
{
    struct Scratch {
        BezierForm form;
        bool busy = false;
    };
    struct ScratchTag;
    Scratch& scratch = threadLocal<Scratch, ScratchTag>();
    if (scratch.busy) {
        use(BezierForm(curve));
        return;
    }
    struct Release {
        Scratch& scratch;
        ~Release()
        {
            scratch.busy = false;
            if (scratch.form.spanCount() * scratch.form.order() > kKeptFormPoints) {
                scratch.form = BezierForm();
            }
        }
    } release{scratch};
    scratch.busy = true;
    scratch.form.rebuild(curve);
    use(scratch.form);
}

} // namespace

bool fitsWholeBezierForm(const CurveRef& curve)
{
    return countNonEmptySpans(curve) * curve.order <= kWholeFormLimit;
}

std::uint32_t clampedSegments(double count)
{
    if (!(count >= 1.0)) {
        return 1;
    }
    return count >= double(kMaxSegmentsPerSpan) ? kMaxSegmentsPerSpan : std::uint32_t(count);
}

namespace {

// The general mapping when given, else the projective one.
template <typename Spans>
void adaptiveImpl(Spans& spans, const TessellationOptions& options, const ViewLimits& limits, TessellatedCurve& out)
{
    if (options.customMapping) {
        Adaptive<Spans>(spans, &options.customMapping, nullptr, limits, out).run(options.c1);
    } else {
        Adaptive<Spans>(spans, nullptr, &options.mapping, limits, out).run(options.c1);
    }
}

// Whether every control point lies strictly outside one plane of the view volume
// in homogeneous frustum coordinates (x = +-w, y = +-w, the hither plane z = 0).
// Each test is linear in the homogeneous point, and the span's points are positive
// combinations of its control points (weights > 0), so the whole span, and every
// chord between two of its points, is outside that plane too. The yon plane is not
// used: culling there would depend on the renderer's depth range.
bool outsideClip(const std::array<double, 16>& m, const Point4* points, unsigned order)
{
    unsigned outside[5] = {0, 0, 0, 0, 0};
    for (unsigned i = 0; i < order; ++i) {
        const Point4& p = points[i];
        double v[4];
        for (int r = 0; r < 4; ++r) {
            v[r] = m[4 * r] * p.x + m[4 * r + 1] * p.y + m[4 * r + 2] * p.z + m[4 * r + 3] * p.w;
        }
        outside[0] += v[0] > v[3] ? 1 : 0;
        outside[1] += -v[0] > v[3] ? 1 : 0;
        outside[2] += v[1] > v[3] ? 1 : 0;
        outside[3] += -v[1] > v[3] ? 1 : 0;
        outside[4] += v[2] > 0.0 ? 1 : 0;
    }
    for (unsigned count : outside) {
        if (count == order) {
            return true;
        }
    }
    return false;
}

// Runs `run(limits)` with the options' limits; the culling captures only a pointer
// to the options, which fits std::function's inline storage (no allocation).
template <typename Run>
void withLimits(const TessellationOptions& options, const Run& run)
{
    if (options.hidden || !(options.cullHiddenSpans && options.hasClip)) {
        run(ViewLimits{options.maxSegments, options.hidden});
        return;
    }
    const SpanCulling culling = [o = &options](const Point4* points, unsigned order) {
        return outsideClip(o->clip, points, order);
    };
    run(ViewLimits{options.maxSegments, culling});
}

void tessellateForm(const BezierForm& form, const TessellationOptions& options, TessellatedCurve& out)
{
    withLimits(options, [&](const ViewLimits& limits) {
        FormSpans spans(form);
        if (options.method == Method::kConstant) {
            constantImpl(spans, options.c1, out, limits);
        } else {
            reset(out);
            adaptiveImpl(spans, options, limits, out);
        }
    });
}

} // namespace

void tessellate(const BezierForm& form, const TessellationOptions& options, TessellatedCurve& out)
{
    tessellateForm(form, options, out);
}

void tessellate(const CurveRef& curve, const TessellationOptions& options, TessellatedCurve& out)
{
    if (!validateCurve(curve).ok()) {
        reset(out);
        return;
    }
    if (options.method == Method::kAdaptive && fitsWholeBezierForm(curve)) {
        withWholeForm(curve, [&](const BezierForm& form) { tessellateForm(form, options, out); });
        return;
    }
    withLimits(options, [&](const ViewLimits& limits) {
        CurveSpans spans(curve);
        if (options.method == Method::kConstant) {
            constantImpl(spans, options.c1, out, limits);
        } else {
            reset(out);
            adaptiveImpl(spans, options, limits, out);
        }
    });
}

bool ProjectiveMapping::operator()(const Point3& local, Point3& mapped) const
{
    const double in[4] = {local.x, local.y, local.z, 1.0};
    double v[4];
    for (int r = 0; r < 4; ++r) {
        v[r] = matrix[r][0] * in[0] + matrix[r][1] * in[1] + matrix[r][2] * in[2] + matrix[r][3];
    }
    if (requirePositiveW ? !(v[3] > 0.0) : v[3] == 0.0) {
        return false;
    }
    if (clipNearer && v[2] > 0.0) {
        return false;
    }
    double out[3];
    for (int k = 0; k < 3; ++k) {
        out[k] = scale[k] == 0.0 ? offset[k] : scale[k] * (v[k] / v[3]) + offset[k];
    }
    mapped = Point3{out[0], out[1], out[2]};
    return std::isfinite(out[0]) && std::isfinite(out[1]) && std::isfinite(out[2]);
}

} // namespace q3::nurbs
