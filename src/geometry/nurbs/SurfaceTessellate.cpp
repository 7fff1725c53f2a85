// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors
//
// Subdividing a NURB patch into triangles under the article's three methods
// ("CONTROLLING SUBDIVISION"), the surface counterpart of Tessellate.cpp.
// Every vertex is the surface evaluated in double at its (u, v) (Surface.cpp);
// the bound is measured between the images of an edge's two vertices, as the
// curve methods measure a segment.
//
// 1. Rows. The domain is cut by rows of constant v, each a polyline of
//    vertices along u; every knot of a non-empty span is a row (in v) and a
//    vertex of every row (in u). Constant method: c2 rows per v span and c1
//    segments per u span at even parameters, every quadrilateral cut along
//    its shorter diagonal (untrimmed patches go straight to the output from
//    here). Adaptive methods: along a row the vertices march as the curves'
//    do, each step ending where the mapped chord lies in [97 %, 100 %] of
//    s = kAlongRows * c1 (probes per span bracket the crossing, a
//    safeguarded regula falsi closes in), except that a step first tries the
//    parameter halfway between two vertices of the row before, so that
//    neighbouring rows alternate; the next row is placed where the largest
//    mapped distance between S(u, v) and S(u, v') over the current row's
//    vertices lies in the same window of h = kAcrossRows * c1.
// 2. Strips. Two neighbouring rows are joined span by span (constant: cell
//    by cell; adaptive: zipping the two polylines, each time taking the
//    shorter of the two possible diagonals). With alternating rows the
//    triangles come out close to equilateral.
// 3. Trims. Each trim curve is subdivided as a NURB curve whose chords are
//    measured on the surface (Tessellate.cpp, with the map
//    (u, v) -> S(u, v) -> measured space), so its chords obey the same bound;
//    each loop's polyline goes into the mesh as constraints (ParamMesh:
//    vertices, then segments by Sloan's flips). A constraint that meets
//    another means the loops cross or touch: the patch is refused. Triangles
//    are then classified by a flood fill that stops at constraints, seeded
//    on the inside of every loop with the loop's own orientation (QD3DGeometry.h:
//    inside a counterclockwise loop is kept, inside a clockwise one not); what
//    no seed reaches is outside every loop, kept when no outermost loop runs
//    counterclockwise. Dropped triangles go.
// 4. Adaptive methods: edges are flipped where the other diagonal of their
//    quadrilateral is shorter; every edge still longer than c1 is split at
//    its parameter midpoint, longest first, with flips around the new vertex
//    (this makes the bound hold where the rows' assumptions do not: curved,
//    sheared or folded parameterisations, cells cut by trims); then vertices
//    are merged into neighbours, shortest edges first, wherever every edge
//    stays within c1 (edge collapse), which takes out what the layout's
//    margins and the span ends left. Knot lines stay edges of the mesh only
//    where the surface has a crease (a knot repeated order - 1 times).
//    An edge with one end without an image (nearer than the hither plane) is
//    measured by the part of it that is drawn: from its visible end to where
//    the chord crosses into the half-space without an image. An edge that a
//    triangle thinner than the key grid blocks (nearly collinear vertices)
//    has the thin triangles around it flipped away first.
//    Screen space: what the view cannot show is not refined (the triangles'
//    Bezier hulls, SurfaceHull) nor laid out densely (visibility cells at the
//    rows' probe intervals).
// 5. Output: each vertex evaluated with its exact partial derivatives for
//    its unit normal, vertices of one row sharing the row's collapsed columns.
//
// The triangle cap (kMaxTriangles) is respected by planning: an adaptive
// layout that would pass 7/8 of it is abandoned early and redone with a
// larger c1 (a constant one with fewer segments per span); the rest is room
// for the refinement, which stops at the cap.

#include "geometry/nurbs/SurfaceTessellate.h"

#include "geometry/nurbs/Evaluate.h"
#include "geometry/nurbs/ParamMesh.h"
#include "geometry/nurbs/SurfaceGrid.h"
#include "geometry/nurbs/SurfaceHull.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <queue>
#include <set>

namespace q3::nurbs {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr std::uint32_t kNone = ParamMesh::kNone;
constexpr std::size_t kLayoutBudget = kMaxTriangles - kMaxTriangles / 8;
constexpr unsigned kMaxIterations = 60;
constexpr std::size_t kMaxRowProbes = 257;
// Most visibility cells a layout tests (Tessellator::setUpCells); a patch with
// more spans is laid out without them.
constexpr std::size_t kMaxCells = std::size_t{1} << 18;

double distance(const Point3& a, const Point3& b)
{
    const double dx = b.x - a.x, dy = b.y - a.y, dz = b.z - a.z;
    return std::sqrt(dx * dx + dy * dy + dz * dz);
}

struct RowPoint {
    double u = 0.0;
    Point3 local;
    Point3 image;
    bool mapped = false;
    bool knot = false;
    bool culled = false; // screen space: both sides of it hidden in the row's band
};

struct Row {
    double v = 0.0;
    std::vector<RowPoint> points;
};

// Thrown (and caught inside this file) when a layout passes its budget.
struct OverBudget {
    double progress; // share of the v domain laid out
};

struct TrimVertex {
    double u, v;
    std::size_t curve;
    double t;
};

struct Constraint {
    std::uint32_t a, b;
    std::size_t loop;
};

class Tessellator {
public:
    Tessellator(const PatchRef& patch, const TessellationOptions& how, TessellatedSurface& out)
        : m_patch(patch), m_s(patch.surface), m_how(how), m_out(out), m_domain(surfaceDomain(m_s)),
          m_uSpans(uSpans(m_s)), m_vSpans(vSpans(m_s)), m_iso(m_s)
    {
        m_mesh.setDomain(m_domain.u0, m_domain.u1, m_domain.v0, m_domain.v1);
        if (how.method == Method::kAdaptive && how.hasClip && how.coarseOutsideClip)
            m_hull.emplace(m_s, how.clip);
        if (how.customMapping)
            m_mapping = how.customMapping;
        else
            m_mapping = [p = &how.mapping](const Point3& local, Point3& image) { return (*p)(local, image); };
    }

    void run()
    {
        if (m_uSpans.empty() || m_vSpans.empty()) {
            clearArrays();
            return;
        }
        m_adaptive = m_how.method == Method::kAdaptive;
        std::vector<Row> rows;
        if (m_adaptive) {
            setUpCells();
            m_c = m_how.c1 > 0.0 ? m_how.c1 : kInfinity;
            m_out.effectiveValue = m_c;
            if (!(m_how.c1 > 0.0))
                m_out.substituted = true;
            planAdaptive(rows);
        } else {
            planConstant(rows);
            if (m_loops.empty() || std::all_of(m_loops.begin(), m_loops.end(),
                                               [](const std::vector<TrimVertex>& l) { return l.empty(); })) {
                emitGrid();
                return;
            }
        }
        clearArrays();
        buildRows(rows);
        rows.clear();
        if (!insertTrims())
            return;
        if (m_adaptive) {
            improve();
            refine();
            coarsen();
            improve();
            // Flips can hand a long edge of a hidden triangle to one that is
            // seen; split what that left too long.
            if (m_hull)
                refine();
        } else if (m_trimmed) {
            improve();
        }
        emit();
    }

private:
    // The caller's storage emptied (its capacity kept); emitGrid overwrites it
    // without this.
    void clearArrays()
    {
        m_out.positions.clear();
        m_out.normals.clear();
        m_out.uvs.clear();
        m_out.parameters.clear();
        m_out.triangles.clear();
    }

    // ---- Measuring ---------------------------------------------------------

    bool mapPoint(const Point3& local, Point3& image) const
    {
        if (!m_adaptive)
            return false;
        if (!m_mapping(local, image))
            return false;
        return std::isfinite(image.x) && std::isfinite(image.y) && std::isfinite(image.z);
    }

    static double chord(const RowPoint& a, const RowPoint& b)
    {
        if (!a.mapped || !b.mapped)
            return kInfinity;
        const double d = distance(a.image, b.image);
        return std::isfinite(d) ? d : kInfinity;
    }

    RowPoint sample(double u) const
    {
        RowPoint p;
        p.u = u;
        p.local = m_iso.point(u);
        p.mapped = mapPoint(p.local, p.image);
        return p;
    }

    // ---- Rows -------------------------------------------------------------

    // Greedy march along the row at v, bound s. With a guide (the row
    // before), a step first tries the parameters halfway between the guide's
    // vertices, so that the two rows' vertices alternate and the triangles
    // between them come out near equilateral; a step where no halfway point
    // lies in [0.4 s, s] is placed by the plain march.
    Row marchRow(double v, double s, const Row* guide = nullptr)
    {
        m_halfway.clear();
        if (guide != nullptr)
            for (std::size_t i = 0; i + 1 < guide->points.size(); ++i)
                m_halfway.push_back(0.5 * (guide->points[i].u + guide->points[i + 1].u));
        std::size_t h = 0;
        m_iso.setV(v, false);
        Row row;
        row.v = v;
        row.points.reserve(m_lastRowSize + m_lastRowSize / 4 + 8);
        RowPoint first = sample(m_uSpans.front().start);
        first.knot = true;
        row.points.push_back(first);
        const unsigned probes = std::max(m_s.uOrder, 8u);
        std::vector<RowPoint> table(probes + 1);
        const std::size_t band = m_culling ? vCell(v) : 0;
        const bool onCut = m_culling && m_vCuts[band] == v && band > 0;
        auto hidden = [&](std::size_t uCell) {
            return m_culling && bandHidden(uCell, band, onCut);
        };
        for (std::size_t si = 0; si < m_uSpans.size(); ++si) {
            const Span& span = m_uSpans[si];
            const std::size_t base = si * probes;
            for (unsigned j = 1; j <= probes; ++j)
                table[j] = sample(j == probes ? span.end : span.start + (span.end - span.start) * j / probes);
            unsigned j = 1;
            // The last step's length in u: the next one is tried at the same
            // length first (neighbouring steps are alike on a smooth row).
            double step = 0.0;
            for (;;) {
                const RowPoint cur = row.points.back();
                while (j <= probes && table[j].u <= cur.u)
                    ++j;
                // A probe interval the view cannot show (on both sides of
                // the row) is crossed in one step, unmeasured.
                if (j <= probes && hidden(base + j - 1)) {
                    if (j < probes) {
                        push(row, table[j]);
                        continue;
                    }
                    break;
                }
                unsigned k = j;
                bool toHidden = false;
                while (k <= probes && chord(cur, table[k]) <= s) {
                    if (k < probes && hidden(base + k)) {
                        toHidden = true;
                        break;
                    }
                    ++k;
                }
                if (toHidden) {
                    push(row, table[k]);
                    continue;
                }
                if (k > probes)
                    break;
                if (!cur.mapped || !table[k].mapped) {
                    // Without an image the step is not measured: up to the
                    // probe (the refinement measures what is drawn).
                    if (k > j && table[k - 1].u > cur.u)
                        push(row, table[k - 1]);
                    if (k < probes)
                        push(row, table[k]);
                    else
                        break;
                    continue;
                }
                RowPoint lo = (k > j && table[k - 1].u > cur.u) ? table[k - 1] : cur;
                RowPoint hi = table[k];
                while (h < m_halfway.size() && m_halfway[h] <= cur.u)
                    ++h;
                bool placed = false;
                for (std::size_t g = h; g < m_halfway.size() && m_halfway[g] < hi.u; ++g) {
                    const RowPoint p = sample(m_halfway[g]);
                    const double d = chord(cur, p);
                    if (!p.mapped || d > s) {
                        if (p.mapped && p.u > lo.u)
                            hi = p;
                        break;
                    }
                    if (d >= 0.4 * s) {
                        step = p.u - cur.u;
                        push(row, p);
                        placed = true;
                        break;
                    }
                    if (p.u > lo.u)
                        lo = p;
                }
                if (placed)
                    continue;
                RowPoint next = closeIn(cur, lo, hi, s, cur.u + step);
                if (!(next.u > cur.u) || next.u >= span.end)
                    break;
                step = next.u - cur.u;
                push(row, next);
            }
            RowPoint end = table[probes];
            end.knot = true;
            if (end.u > row.points.back().u)
                push(row, end);
            else
                row.points.back().knot = true;
        }
        m_lastRowSize = row.points.size();
        if (m_culling)
            for (RowPoint& p : row.points) {
                // The cells on both sides of p, in the row's band.
                const std::size_t c = cellOf(m_uCuts, p.u);
                p.culled = hidden(c) && (m_uCuts[c] != p.u || c == 0 || hidden(c - 1));
            }
        return row;
    }

    // ---- Visibility cells (screen space) ----------------------------------

    // The layout's probe intervals (max(order, 8) per span in each
    // direction) cut the domain into cells; a cell whose piece of surface
    // lies outside one plane of the view volume (SurfaceHull) is hidden. The
    // rows march across an interval hidden in the cells on both sides of the
    // row in one step, and rows are placed by the distances at the vertices
    // that are not so culled: a patch mostly outside the view is laid out
    // densely only near what can be seen. (The refinement still splits every
    // edge of a triangle that may be seen.) Off when nothing is hidden, so
    // the layout is then the same as without a view.
    void setUpCells()
    {
        m_culling = false;
        if (!m_hull)
            return;
        const unsigned pu = std::max(m_s.uOrder, 8u), pv = std::max(m_s.vOrder, 8u);
        auto cuts = [](const std::vector<Span>& spans, unsigned probes, std::vector<double>& out) {
            out.clear();
            for (const Span& span : spans)
                for (unsigned i = 0; i < probes; ++i)
                    out.push_back(span.start + (span.end - span.start) * i / probes);
            out.push_back(spans.back().end);
        };
        const std::size_t columns = m_uSpans.size() * pu, rows = m_vSpans.size() * pv;
        if (columns * rows > kMaxCells)
            return;
        cuts(m_uSpans, pu, m_uCuts);
        cuts(m_vSpans, pv, m_vCuts);
        m_cellColumns = columns;
        m_hiddenCells.assign(columns * rows, 0);
        bool any = false;
        for (std::size_t sv = 0; sv < m_vSpans.size(); ++sv)
            for (std::size_t su = 0; su < m_uSpans.size(); ++su) {
                const Span& a = m_uSpans[su];
                const Span& b = m_vSpans[sv];
                const bool whole = m_hull->outside(a.start, a.end, b.start, b.end);
                if (!whole && m_hull->inside(a.start, a.end, b.start, b.end))
                    continue;
                for (unsigned j = 0; j < pv; ++j)
                    for (unsigned i = 0; i < pu; ++i) {
                        const std::size_t cu = su * pu + i, cv = sv * pv + j;
                        const bool out = whole || m_hull->outside(m_uCuts[cu], m_uCuts[cu + 1], m_vCuts[cv],
                                                                  m_vCuts[cv + 1]);
                        m_hiddenCells[cv * columns + cu] = out ? 1 : 0;
                        any = any || out;
                    }
            }
        m_culling = any;
    }

    // The cell (interval between cuts) holding t: the last cut at or before it.
    static std::size_t cellOf(const std::vector<double>& cuts, double t)
    {
        const auto it = std::upper_bound(cuts.begin(), cuts.end(), t);
        const std::size_t i = it == cuts.begin() ? 0 : std::size_t(it - cuts.begin()) - 1;
        return std::min(i, cuts.size() - 2);
    }
    std::size_t vCell(double v) const { return cellOf(m_vCuts, v); }

    // Whether u cell `column` is hidden in the band of a row in v cell `band`
    // (and in the cell below, for a row on a cut).
    bool bandHidden(std::size_t column, std::size_t band, bool onCut) const
    {
        if (!m_hiddenCells[band * m_cellColumns + column])
            return false;
        return !onCut || m_hiddenCells[(band - 1) * m_cellColumns + column] != 0;
    }

    void push(Row& row, const RowPoint& p)
    {
        row.points.push_back(p);
        if (++m_layoutVertices > m_vertexBudget)
            throw OverBudget{m_vProgress};
    }

    // Safeguarded regula falsi for the point between lo and hi whose chord
    // from `from` lies in [(1 - tol) s, s]; chord(from, lo) <= s < chord(from, hi).
    RowPoint closeIn(const RowPoint& from, RowPoint lo, RowPoint hi, double s, double guess) const
    {
        double dlo = lo.u > from.u ? chord(from, lo) : 0.0;
        double dhi = chord(from, hi);
        const double accept = (1.0 - kStepTolerance) * s;
        const double target = (1.0 - 0.5 * kStepTolerance) * s;
        // Samples u and keeps it as the end of the bracket on its side of s.
        const auto narrow = [&](double u) {
            const RowPoint p = sample(u);
            const double d = chord(from, p);
            if (d <= s) {
                lo = p;
                dlo = d;
            } else {
                hi = p;
                dhi = d;
            }
        };
        if (lo.u < guess && guess < hi.u && dlo < accept)
            narrow(guess);
        for (unsigned iteration = 0; iteration < kMaxIterations && dlo < accept; ++iteration) {
            double f = 0.5;
            if (iteration % 3 != 2 && std::isfinite(dhi))
                f = std::min(0.95, std::max(0.05, (target - dlo) / (dhi - dlo)));
            const double u = lo.u + (hi.u - lo.u) * f;
            if (!(lo.u < u && u < hi.u))
                break;
            narrow(u);
        }
        if (lo.u > from.u)
            return lo;
        return sample(0.5 * (from.u + hi.u));
    }

    // The largest mapped distance between the current row's probes and the
    // surface at v'; `unmapped` when a probe has no image at either end.
    double rowDistance(const std::vector<const RowPoint*>& probes, double v, bool& unmapped)
    {
        m_iso.setV(v, false);
        unmapped = false;
        double worst = 0.0;
        for (const RowPoint* p : probes) {
            if (!p->mapped) {
                unmapped = true;
                continue;
            }
            Point3 image;
            if (!mapPoint(m_iso.point(p->u), image)) {
                unmapped = true;
                continue;
            }
            worst = std::max(worst, distance(p->image, image));
        }
        return worst;
    }

    void layoutAdaptive(std::vector<Row>& rows)
    {
        const double s = kAlongRows * m_c;
        const double h = kAcrossRows * m_c;
        m_layoutVertices = 0;
        m_vProgress = 0.0;
        rows.clear();
        rows.push_back(marchRow(m_vSpans.front().start, s));
        const unsigned probes = std::max(m_s.vOrder, 8u);
        const double height = m_domain.v1 - m_domain.v0;
        std::vector<const RowPoint*> probePoints;
        double rowStep = 0.0;
        for (const Span& span : m_vSpans) {
            for (;;) {
                const Row& cur = rows.back();
                if (!(cur.v < span.end))
                    break;
                m_vProgress = (cur.v - m_domain.v0) / height;
                probePoints.clear();
                const std::size_t n = cur.points.size();
                const std::size_t stride = n > kMaxRowProbes ? (n + kMaxRowProbes - 1) / kMaxRowProbes : 1;
                for (std::size_t i = 0; i < n; ++i)
                    if ((i % stride == 0 || cur.points[i].knot) && !cur.points[i].culled)
                        probePoints.push_back(&cur.points[i]);
                // With parts hidden, every cut of the visibility cells is
                // reached by a row, so that strips stay inside the bands
                // the rows were culled by.
                const double ceiling =
                    m_culling ? *std::upper_bound(m_vCuts.begin(), m_vCuts.end(), cur.v) : span.end;
                // Scan the span's probe rows for the first one too far (or
                // without an image), then close in.
                double lo = cur.v;
                double dlo = 0.0;
                double next = span.end;
                bool found = false;
                // Try the last strip's height first.
                if (rowStep > 0.0 && cur.v + rowStep < span.end && cur.v + rowStep <= ceiling) {
                    bool unmapped = false;
                    const double guess = cur.v + rowStep;
                    const double d = rowDistance(probePoints, guess, unmapped);
                    if (!unmapped && d <= h && d >= (1.0 - kStepTolerance) * h) {
                        rows.push_back(marchRow(guess, s, &cur));
                        continue;
                    }
                }
                for (unsigned i = 1; i <= probes; ++i) {
                    const double vi = i == probes ? span.end : span.start + (span.end - span.start) * i / probes;
                    if (!(vi > cur.v))
                        continue;
                    bool unmapped = false;
                    const double d = rowDistance(probePoints, vi, unmapped);
                    if (unmapped) {
                        next = lo > cur.v ? lo : vi;
                        found = true;
                        break;
                    }
                    if (d > h) {
                        next = closeInRow(probePoints, cur.v, lo, dlo, vi, d, h);
                        found = true;
                        break;
                    }
                    lo = vi;
                    dlo = d;
                }
                if (!found)
                    next = span.end;
                next = std::min(next, ceiling);
                if (m_mesh.keyY(next) == m_mesh.keyY(cur.v))
                    next = std::min(span.end, cur.v + height / double(ParamMesh::kGrid) * 2.0);
                if (!(next > cur.v))
                    next = span.end;
                rowStep = next - cur.v;
                rows.push_back(marchRow(next, s, &cur));
            }
        }
    }

    double closeInRow(const std::vector<const RowPoint*>& probes, double from, double lo, double dlo, double hi,
                      double dhi, double h)
    {
        const double accept = (1.0 - kStepTolerance) * h;
        const double target = (1.0 - 0.5 * kStepTolerance) * h;
        for (unsigned iteration = 0; iteration < kMaxIterations && dlo < accept; ++iteration) {
            double f = 0.5;
            if (iteration % 3 != 2 && std::isfinite(dhi))
                f = std::min(0.95, std::max(0.05, (target - dlo) / (dhi - dlo)));
            const double v = lo + (hi - lo) * f;
            if (!(lo < v && v < hi))
                break;
            bool unmapped = false;
            const double d = rowDistance(probes, v, unmapped);
            if (!unmapped && d <= h) {
                lo = v;
                dlo = d;
            } else {
                hi = v;
                dhi = unmapped ? kInfinity : d;
            }
        }
        return lo > from ? lo : 0.5 * (from + hi);
    }

    void planAdaptive(std::vector<Row>& rows)
    {
        m_vertexBudget = kLayoutBudget / 2;
        for (int attempt = 0; attempt < 8; ++attempt) {
            try {
                layoutAdaptive(rows);
                if (trimBudgetFits())
                    return;
                throw OverBudget{1.0};
            } catch (const OverBudget& over) {
                rows.clear();
                const double progress = std::max(over.progress, 1e-3);
                const double factor =
                    std::min(1e6, std::max(1.5, 1.1 * std::sqrt(double(m_layoutVertices) / progress /
                                                                double(m_vertexBudget))));
                m_c = std::isfinite(m_c) ? m_c * factor : m_c;
                m_out.substituted = true;
                m_out.effectiveValue = m_c;
            }
        }
        // One quadrilateral per pair of spans.
        m_c = kInfinity;
        m_out.effectiveValue = kInfinity;
        m_vertexBudget = std::numeric_limits<std::size_t>::max();
        layoutGrid(rows, 1, 1);
        trimBudgetFits();
    }

    // Whether the trim loops, subdivided under the current bound, fit what
    // the layout left of the budget; keeps their polylines.
    bool trimBudgetFits()
    {
        m_loops.clear();
        std::size_t total = 0;
        for (std::size_t l = 0; l < m_patch.loops.size(); ++l) {
            m_loops.emplace_back();
            for (std::size_t c = 0; c < m_patch.loops[l].size(); ++c) {
                subdivideTrim(l, c, m_loops.back());
                total = m_loops.back().size() + total;
                if (m_layoutVertices + total > m_vertexBudget)
                    return false;
            }
        }
        return true;
    }

    void subdivideTrim(std::size_t loop, std::size_t curve, std::vector<TrimVertex>& out) const
    {
        const PlanarCurve planar(m_patch.loops[loop][curve]);
        const CurveRef ref = planar.ref();
        TessellatedCurve polyline;
        if (m_adaptive && std::isfinite(m_c)) {
            const SurfaceRef s = m_s;
            const PointMapping& map = m_mapping;
            const PointMapping onSurface = [&s, &map](const Point3& p, Point3& image) {
                return map(evaluateSurface(s, p.x, p.y), image);
            };
            // A hair below c1, so that rounding the ends to the mesh's keys
            // cannot take a chord past it.
            TessellationOptions options;
            options.method = Method::kAdaptive;
            options.c1 = m_c * (1.0 - 1e-9);
            options.customMapping = onSurface;
            tessellate(ref, options, polyline);
        } else {
            TessellationOptions options;
            options.c1 = m_adaptive ? 1u : m_uSegments;
            tessellate(ref, options, polyline);
        }
        // Every vertex but the curve's end (the next curve's start stands for it).
        const std::size_t count = polyline.parameters.size();
        for (std::size_t k = 0; k + 1 < count; ++k) {
            const double t = polyline.parameters[k];
            const Point3 p = evaluate(ref, t).point;
            out.push_back(TrimVertex{std::min(std::max(p.x, m_domain.u0), m_domain.u1),
                                     std::min(std::max(p.y, m_domain.v0), m_domain.v1), curve, t});
        }
        if (count == 1) {
            const Point3 p = evaluate(ref, polyline.parameters[0]).point;
            out.push_back(TrimVertex{std::min(std::max(p.x, m_domain.u0), m_domain.u1),
                                     std::min(std::max(p.y, m_domain.v0), m_domain.v1), curve,
                                     polyline.parameters[0]});
        }
    }

    // Constant: segments per span in u and rows per span in v, evenly spaced.
    void layoutGrid(std::vector<Row>& rows, std::uint32_t m, std::uint32_t n)
    {
        rows.clear();
        std::vector<double> us;
        std::vector<char> uKnot;
        for (const Span& span : m_uSpans)
            for (std::uint32_t j = 0; j < m; ++j) {
                us.push_back(span.start + (span.end - span.start) * double(j) / double(m));
                uKnot.push_back(j == 0);
            }
        us.push_back(m_uSpans.back().end);
        uKnot.push_back(1);
        auto addRow = [&](double v) {
            m_iso.setV(v, false);
            Row row;
            row.v = v;
            row.points.resize(us.size());
            for (std::size_t i = 0; i < us.size(); ++i) {
                RowPoint& p = row.points[i];
                p.u = us[i];
                p.local = m_iso.point(us[i]);
                p.knot = uKnot[i] != 0;
            }
            rows.push_back(std::move(row));
        };
        for (const Span& span : m_vSpans)
            for (std::uint32_t j = 0; j < n; ++j)
                addRow(span.start + (span.end - span.start) * double(j) / double(n));
        addRow(m_vSpans.back().end);
        m_gridRows = true;
    }

    void planConstant(std::vector<Row>& rows)
    {
        std::uint32_t m = clampedSegments(m_how.c1);
        std::uint32_t n = clampedSegments(m_how.c2);
        const double spanPairs = double(m_uSpans.size()) * double(m_vSpans.size());
        bool lowered = double(m) != m_how.c1 || double(n) != m_how.c2;
        if (2.0 * double(m) * double(n) * spanPairs > double(kLayoutBudget)) {
            const double f = std::sqrt(double(kLayoutBudget) / (2.0 * double(m) * double(n) * spanPairs));
            m = std::max<std::uint32_t>(1, std::uint32_t(double(m) * f));
            n = std::max<std::uint32_t>(1, std::uint32_t(double(n) * f));
            while (2.0 * double(m) * double(n) * spanPairs > double(kLayoutBudget) && (m > 1 || n > 1)) {
                if (m >= n)
                    --m;
                else
                    --n;
            }
            lowered = true;
        }
        // Trim curves get m segments per span; keep them within the budget too.
        std::size_t trimSpans = 0;
        for (const auto& loop : m_patch.loops)
            for (const TrimCurveRef& curve : loop)
                trimSpans += countNonEmptySpans(PlanarCurve(curve).ref());
        while (m > 1 && double(trimSpans) * double(m) > double(kMaxTriangles / 8)) {
            m = std::max<std::uint32_t>(1, m / 2);
            lowered = true;
        }
        m_uSegments = m;
        m_vSegments = n;
        m_out.uSegments = m;
        m_out.vSegments = n;
        m_out.substituted = lowered;
        m_out.effectiveValue = double(m) * double(n);
        m_loops.clear();
        for (std::size_t l = 0; l < m_patch.loops.size(); ++l) {
            m_loops.emplace_back();
            for (std::size_t c = 0; c < m_patch.loops[l].size(); ++c)
                subdivideTrim(l, c, m_loops.back());
        }
        if (!m_patch.loops.empty())
            layoutGrid(rows, m, n);
    }

    // The untrimmed constant method straight to the output: the grid of
    // vertices by evaluateGrid (the basis of every distinct u and v computed
    // once, rows through the contraction several at a time), and each
    // quadrilateral cut along its shorter diagonal.
    void emitGrid()
    {
        const std::uint32_t m = m_uSegments, n = m_vSegments;
        std::vector<double> us, vs;
        us.reserve(m_uSpans.size() * m + 1);
        vs.reserve(m_vSpans.size() * n + 1);
        for (const Span& span : m_uSpans)
            for (std::uint32_t j = 0; j < m; ++j)
                us.push_back(span.start + (span.end - span.start) * double(j) / double(m));
        us.push_back(m_uSpans.back().end);
        for (const Span& span : m_vSpans)
            for (std::uint32_t j = 0; j < n; ++j)
                vs.push_back(span.start + (span.end - span.start) * double(j) / double(n));
        vs.push_back(m_vSpans.back().end);
        const std::size_t columns = us.size(), rowCount = vs.size();
        const std::size_t count = columns * rowCount;
        // Storage is reused from the caller's last call: resize without clearing
        // first, so that nothing is written twice.
        m_out.positions.resize(3 * count);
        m_out.normals.resize(3 * count);
        m_out.uvs.resize(2 * count);
        m_out.parameters.resize(2 * count);
        evaluateGrid(m_s, us.data(), columns, vs.data(), rowCount, m_out.positions.data(), m_out.normals.data());
        float* uv = m_out.uvs.data();
        double* parameter = m_out.parameters.data();
        for (std::size_t r = 0; r < rowCount; ++r)
            for (std::size_t i = 0; i < columns; ++i) {
                uv[0] = float(us[i]);
                uv[1] = float(vs[r]);
                parameter[0] = us[i];
                parameter[1] = vs[r];
                uv += 2;
                parameter += 2;
            }
        m_out.triangles.resize(6 * (columns - 1) * (rowCount - 1));
        std::uint32_t* out = m_out.triangles.data();
        const float* p = m_out.positions.data();
        auto squared = [p](std::uint32_t x, std::uint32_t y) {
            const float dx = p[3 * y] - p[3 * x], dy = p[3 * y + 1] - p[3 * x + 1], dz = p[3 * y + 2] - p[3 * x + 2];
            return dx * dx + dy * dy + dz * dz;
        };
        for (std::size_t r = 0; r + 1 < rowCount; ++r)
            for (std::size_t i = 0; i + 1 < columns; ++i) {
                const std::uint32_t a = std::uint32_t(r * columns + i), b = a + 1;
                const std::uint32_t d = std::uint32_t((r + 1) * columns + i), c = d + 1;
                const bool ac = squared(a, c) <= squared(b, d);
                out[0] = a;
                out[1] = b;
                out[2] = ac ? c : d;
                out[3] = ac ? a : b;
                out[4] = c;
                out[5] = d;
                out += 6;
            }
    }

    void writeVertex(std::size_t i, const SurfacePoint& p, double u, double v)
    {
        m_out.positions[3 * i] = float(p.point.x);
        m_out.positions[3 * i + 1] = float(p.point.y);
        m_out.positions[3 * i + 2] = float(p.point.z);
        m_out.normals[3 * i] = float(p.normal.x);
        m_out.normals[3 * i + 1] = float(p.normal.y);
        m_out.normals[3 * i + 2] = float(p.normal.z);
        m_out.uvs[2 * i] = float(u);
        m_out.uvs[2 * i + 1] = float(v);
        m_out.parameters[2 * i] = u;
        m_out.parameters[2 * i + 1] = v;
    }

    // ---- The mesh -----------------------------------------------------------

    std::uint32_t addMeshVertex(double u, double v, std::int64_t x, std::int64_t y, const Point3& local)
    {
        const std::uint32_t id = m_mesh.addVertex(u, v, x, y);
        setVertexData(id, local);
        return id;
    }

    void setVertexData(std::uint32_t id, const Point3& local)
    {
        if (m_local.size() <= id) {
            m_local.resize(id + 1);
            m_image.resize(id + 1);
            m_mapped.resize(id + 1, 0);
        }
        m_local[id] = local;
        m_mapped[id] = mapPoint(local, m_image[id]) ? 1 : 0;
    }

    // Lengths where they are measured (mapped), or in the patch's own
    // coordinates where they are not (constant method, points without an image).
    double metric(std::uint32_t a, std::uint32_t b) const
    {
        if (m_adaptive && m_mapped[a] && m_mapped[b])
            return distance(m_image[a], m_image[b]);
        return distance(m_local[a], m_local[b]);
    }

    void buildRows(const std::vector<Row>& rows)
    {
        std::vector<std::array<std::uint32_t, 3>> corners;
        std::vector<std::vector<std::uint32_t>> ids(rows.size());
        std::vector<std::vector<std::size_t>> knots(rows.size());
        std::int64_t lastY = -1;
        std::vector<std::size_t> kept;
        for (std::size_t r = 0; r < rows.size(); ++r) {
            const std::int64_t y = m_mesh.keyY(rows[r].v);
            if (y == lastY)
                continue; // thinner than a key cell: merged with the row before
            lastY = y;
            kept.push_back(r);
            std::vector<std::uint32_t>& row = ids[r];
            std::int64_t lastX = -1;
            for (const RowPoint& p : rows[r].points) {
                const std::int64_t x = m_mesh.keyX(p.u);
                if (x == lastX) {
                    if (p.knot) {
                        // The knot's vertex replaces its neighbour's.
                        ParamMesh::Vertex& vertex = m_mesh.vertices[row.back()];
                        vertex.u = p.u;
                        setVertexData(row.back(), p.local);
                        if (knots[r].empty() || knots[r].back() != row.size() - 1)
                            knots[r].push_back(row.size() - 1);
                    }
                    continue;
                }
                lastX = x;
                if (p.knot)
                    knots[r].push_back(row.size());
                row.push_back(addMeshVertex(p.u, rows[r].v, x, y, p.local));
            }
        }
        // The first and last vertex of every row are knots (the domain's ends).
        for (std::size_t k = 0; k + 1 < kept.size(); ++k) {
            const std::size_t rb = kept[k], rt = kept[k + 1];
            const std::vector<std::uint32_t>& bottom = ids[rb];
            const std::vector<std::uint32_t>& top = ids[rt];
            const std::vector<std::size_t>& kb = knots[rb];
            const std::vector<std::size_t>& kt = knots[rt];
            if (kb.size() != kt.size())
                continue; // not expected: every row has every knot
            for (std::size_t s = 0; s + 1 < kb.size(); ++s)
                zip(bottom, kb[s], kb[s + 1], top, kt[s], kt[s + 1], corners);
        }
        m_mesh.build(corners);
        // Knot lines: along every row that lies on a v knot and across every
        // strip at every u knot; the adaptive methods keep only creases
        // (the others may be flipped and collapsed like any edge).
        auto crease = [&](const float* knotVector, std::size_t count, unsigned order, double value) {
            if (!m_adaptive)
                return true;
            const std::size_t multiplicity = std::size_t(std::count(knotVector, knotVector + count, float(value)));
            return multiplicity + 1 >= order;
        };
        const std::size_t uKnotCount = m_s.numColumns + m_s.uOrder, vKnotCount = m_s.numRows + m_s.vOrder;
        for (std::size_t k = 0; k < kept.size(); ++k) {
            const std::size_t r = kept[k];
            const bool onKnot = std::any_of(m_vSpans.begin(), m_vSpans.end(),
                                            [&](const Span& span) { return span.start == rows[r].v; });
            if (onKnot && k > 0 && crease(m_s.vKnots, vKnotCount, m_s.vOrder, rows[r].v))
                for (std::size_t i = 0; i + 1 < ids[r].size(); ++i)
                    m_mesh.markFixed(ids[r][i], ids[r][i + 1]);
            if (k + 1 < kept.size() && knots[r].size() == knots[kept[k + 1]].size())
                for (std::size_t j = 1; j + 1 < knots[r].size(); ++j)
                    if (j - 1 < m_uSpans.size() && crease(m_s.uKnots, uKnotCount, m_s.uOrder, m_uSpans[j - 1].end))
                        m_mesh.markFixed(ids[r][knots[r][j]], ids[kept[k + 1]][knots[kept[k + 1]][j]]);
        }
    }

    // Triangles between bottom[b0 .. b1] and top[t0 .. t1] (same u at both
    // ends), counterclockwise in (u, v).
    void zip(const std::vector<std::uint32_t>& bottom, std::size_t b0, std::size_t b1,
             const std::vector<std::uint32_t>& top, std::size_t t0, std::size_t t1,
             std::vector<std::array<std::uint32_t, 3>>& corners) const
    {
        if (m_gridRows && b1 - b0 == t1 - t0) {
            for (std::size_t i = 0; b0 + i < b1; ++i) {
                const std::uint32_t a = bottom[b0 + i], b = bottom[b0 + i + 1];
                const std::uint32_t c = top[t0 + i + 1], d = top[t0 + i];
                if (metric(a, c) <= metric(b, d)) {
                    corners.push_back({a, b, c});
                    corners.push_back({a, c, d});
                } else {
                    corners.push_back({a, b, d});
                    corners.push_back({b, c, d});
                }
            }
            return;
        }
        std::size_t i = b0, k = t0;
        while (i < b1 || k < t1) {
            bool advanceBottom;
            if (i == b1)
                advanceBottom = false;
            else if (k == t1)
                advanceBottom = true;
            else
                advanceBottom = metric(bottom[i + 1], top[k]) <= metric(bottom[i], top[k + 1]);
            if (advanceBottom) {
                corners.push_back({bottom[i], bottom[i + 1], top[k]});
                ++i;
            } else {
                corners.push_back({bottom[i], top[k + 1], top[k]});
                ++k;
            }
        }
    }

    // ---- Trims ------------------------------------------------------------

    void fail(std::size_t loop, std::size_t other, double u, double v)
    {
        m_out.crossing = true;
        m_out.crossingLoop = std::min(loop, other);
        m_out.crossingOther = std::max(loop, other);
        m_out.crossingU = u;
        m_out.crossingV = v;
    }

    bool insertTrims()
    {
        // Each loop's polyline on the keys, without repeats; loops enclosing
        // no area bound nothing and are left out.
        struct Polyline {
            std::size_t loop;
            std::vector<TrimVertex> points;
            std::vector<std::int64_t> x, y;
            bool ccw;
        };
        std::vector<Polyline> polylines;
        for (std::size_t l = 0; l < m_loops.size(); ++l) {
            Polyline line;
            line.loop = l;
            for (const TrimVertex& p : m_loops[l]) {
                const std::int64_t x = m_mesh.keyX(p.u), y = m_mesh.keyY(p.v);
                if (!line.x.empty() && line.x.back() == x && line.y.back() == y)
                    continue;
                line.points.push_back(p);
                line.x.push_back(x);
                line.y.push_back(y);
            }
            while (line.x.size() > 1 && line.x.back() == line.x.front() && line.y.back() == line.y.front()) {
                line.points.pop_back();
                line.x.pop_back();
                line.y.pop_back();
            }
            if (line.x.size() < 3)
                continue;
            __int128 area = 0;
            for (std::size_t i = 0, n = line.x.size(); i < n; ++i) {
                const std::size_t j = (i + 1) % n;
                area += __int128(line.x[i]) * line.y[j] - __int128(line.x[j]) * line.y[i];
            }
            if (area == 0)
                continue;
            line.ccw = area > 0;
            polylines.push_back(std::move(line));
        }
        m_trimmed = !polylines.empty();
        if (!m_trimmed)
            return true;
        m_ccw.assign(m_loops.size(), true);
        std::uint32_t hint = 0;
        for (const Polyline& line : polylines) {
            m_ccw[line.loop] = line.ccw;
            std::vector<std::uint32_t> ids;
            for (std::size_t i = 0; i < line.points.size(); ++i) {
                const TrimVertex& p = line.points[i];
                const ParamMesh::Location where = m_mesh.locate(line.x[i], line.y[i], hint);
                if (where.kind == ParamMesh::Location::kOutside) {
                    fail(line.loop, line.loop, p.u, p.v);
                    return false;
                }
                const ParamMesh::Triangle& tri = m_mesh.triangles[where.triangle];
                if (where.kind == ParamMesh::Location::kOnEdge && ((tri.constrained >> where.index) & 1u)) {
                    const std::uint32_t other = tri.v[(where.index + 1) % 3];
                    fail(line.loop, std::size_t(std::max(0, m_mesh.vertices[other].loop)), p.u, p.v);
                    return false;
                }
                bool existed = false;
                const std::uint32_t id =
                    m_mesh.insertVertex(p.u, p.v, line.x[i], line.y[i], where.triangle, existed);
                if (id == kNone) {
                    fail(line.loop, line.loop, p.u, p.v);
                    return false;
                }
                ParamMesh::Vertex& vertex = m_mesh.vertices[id];
                if (existed && vertex.loop >= 0) {
                    fail(line.loop, std::size_t(vertex.loop), p.u, p.v);
                    return false;
                }
                vertex.u = p.u;
                vertex.v = p.v;
                vertex.loop = std::int32_t(line.loop);
                setVertexData(id, evaluateSurface(m_s, p.u, p.v));
                ids.push_back(id);
                hint = m_mesh.vertices[id].triangle;
            }
            for (std::size_t i = 0, n = ids.size(); i < n; ++i) {
                const std::size_t j = (i + 1) % n;
                const TrimVertex& from = line.points[i];
                const TrimVertex& to = line.points[j];
                const auto keep = [&](std::uint32_t w) { return straightThrough(line.loop, from, to, w); };
                const ParamMesh::SegmentResult result = m_mesh.insertSegment(ids[i], ids[j], keep);
                if (result == ParamMesh::SegmentResult::kCrossesConstraint) {
                    fail(line.loop, crossedLoop(), m_mesh.crossU, m_mesh.crossV);
                    return false;
                }
                if (result == ParamMesh::SegmentResult::kTouchesVertex) {
                    const ParamMesh::Vertex& touched = m_mesh.vertices[m_mesh.touchVertex];
                    fail(line.loop, std::size_t(std::max(0, touched.loop)), touched.u, touched.v);
                    return false;
                }
                if (result == ParamMesh::SegmentResult::kStuck) {
                    fail(line.loop, line.loop, from.u, from.v);
                    return false;
                }
                for (const auto& piece : m_mesh.pieces)
                    m_constraints.push_back(Constraint{piece.first, piece.second, line.loop});
            }
        }
        classify();
        return true;
    }

    // The loop of the constrained edge insertSegment ran into.
    std::size_t crossedLoop() const
    {
        const std::int32_t loop = m_mesh.vertices[m_mesh.crossA].loop;
        return loop >= 0 ? std::size_t(loop) : 0;
    }

    // A vertex of the mesh that a trim chord runs exactly through stays (as
    // part of the loop) when the trim curve is straight there (its chord
    // midpoint within a key cell of the curve), and is removed otherwise.
    bool straightThrough(std::size_t loop, const TrimVertex& from, const TrimVertex& to, std::uint32_t) const
    {
        if (from.curve != to.curve)
            return false;
        const PlanarCurve planar(m_patch.loops[loop][from.curve]);
        const Point3 mid = evaluate(planar.ref(), 0.5 * (from.t + to.t)).point;
        const std::int64_t dx = m_mesh.keyX(mid.x) - m_mesh.keyX(0.5 * (from.u + to.u));
        const std::int64_t dy = m_mesh.keyY(mid.y) - m_mesh.keyY(0.5 * (from.v + to.v));
        return std::llabs(dx) <= 1 && std::llabs(dy) <= 1;
    }

    void classify()
    {
        const std::size_t count = m_mesh.triangles.size();
        std::vector<std::int8_t> state(count, -1);
        std::vector<std::uint32_t> queue;
        auto flood = [&](std::vector<std::size_t>* outermost) {
            while (!queue.empty()) {
                const std::uint32_t t = queue.back();
                queue.pop_back();
                const ParamMesh::Triangle& tri = m_mesh.triangles[t];
                for (int e = 0; e < 3; ++e) {
                    const std::uint32_t n = tri.neighbour[e];
                    if (n == kNone)
                        continue;
                    if ((tri.constrained >> e) & 1u) {
                        if (outermost != nullptr) {
                            const std::int32_t loop = m_mesh.vertices[tri.v[(e + 1) % 3]].loop;
                            if (loop >= 0)
                                outermost->push_back(std::size_t(loop));
                        }
                        continue;
                    }
                    if (state[n] < 0) {
                        state[n] = state[t];
                        queue.push_back(n);
                    }
                }
            }
        };
        for (const Constraint& c : m_constraints) {
            std::uint32_t t;
            int e;
            const bool ccw = m_ccw[c.loop];
            // The inside of a counterclockwise loop is on its left (the
            // triangle holding a -> b), of a clockwise one on its right.
            const bool found = ccw ? m_mesh.findEdge(c.a, c.b, t, e) : m_mesh.findEdge(c.b, c.a, t, e);
            if (found && state[t] < 0) {
                state[t] = ccw ? 1 : 0;
                queue.push_back(t);
            }
        }
        flood(nullptr);
        // What no seed reached is outside every loop.
        std::vector<std::size_t> outermost;
        std::vector<std::uint32_t> unreached;
        for (std::uint32_t t = 0; t < count; ++t)
            if (m_mesh.triangles[t].alive && state[t] < 0) {
                state[t] = 2;
                queue.push_back(t);
                flood(&outermost);
                unreached.push_back(t);
            }
        bool keepOutside = true;
        for (std::size_t loop : outermost)
            if (m_ccw[loop])
                keepOutside = false;
        for (std::uint32_t t = 0; t < count; ++t) {
            if (!m_mesh.triangles[t].alive)
                continue;
            const bool kept = state[t] == 2 ? keepOutside : state[t] == 1;
            if (!kept)
                m_mesh.kill(t);
        }
        m_mesh.refreshVertexTriangles();
    }

    // ---- Improvement and refinement ----------------------------------------

    bool flippable(std::uint32_t t, int e) const
    {
        const ParamMesh::Triangle& tri = m_mesh.triangles[t];
        return tri.neighbour[e] != kNone && !((tri.constrained >> e) & 1u) && !((tri.fixed >> e) & 1u);
    }

    std::uint32_t opposite(std::uint32_t t, int e) const
    {
        const ParamMesh::Triangle& tri = m_mesh.triangles[t];
        const std::uint32_t n = tri.neighbour[e];
        const std::uint32_t a = tri.v[(e + 1) % 3], b = tri.v[(e + 2) % 3];
        for (std::uint32_t w : m_mesh.triangles[n].v)
            if (w != a && w != b)
                return w;
        return kNone;
    }

    // Whether diagonal (r, s) should replace (a, b): it is shorter where
    // lengths are measured; in the adaptive methods, where a corner has no
    // image, by the part that is drawn, so that no flip can lengthen what is
    // drawn.
    bool shorterDiagonal(std::uint32_t r, std::uint32_t s, std::uint32_t a, std::uint32_t b) const
    {
        // The triangles (r, a, s) and (r, s, b) the flip makes must not be
        // slivers in (u, v): a vertex within a key cell or so of the opposite
        // side leaves an edge that no point of the key grid can split.
        if (!roomy(r, a, s) || !roomy(r, s, b))
            return false;
        if (m_adaptive && !(m_mapped[r] && m_mapped[s] && m_mapped[a] && m_mapped[b])) {
            const double now = drawnLength(a, b);
            return now > 0.0 && drawnLength(r, s) < now * (1.0 - 1e-12);
        }
        return metric(r, s) < metric(a, b) * (1.0 - 1e-12);
    }

    // Whether triangle (a, b, c), counterclockwise on the keys, is at least
    // 1/10,000 of its longest side (and eight key cells) high over it: a flip
    // may not make anything thinner.
    bool roomy(std::uint32_t a, std::uint32_t b, std::uint32_t c) const
    {
        const std::int64_t twice = m_mesh.orient(a, b, c);
        if (twice <= 0)
            return false;
        const ParamMesh::Vertex& p = m_mesh.vertices[a];
        const ParamMesh::Vertex& q = m_mesh.vertices[b];
        const ParamMesh::Vertex& w = m_mesh.vertices[c];
        auto length = [](const ParamMesh::Vertex& x, const ParamMesh::Vertex& y) {
            return std::hypot(double(x.x - y.x), double(x.y - y.y));
        };
        const double longest = std::max({length(p, q), length(q, w), length(w, p)});
        return double(twice) >= longest * std::max(8.0, 1e-4 * longest);
    }

    // Flips edge (a, b) when the other diagonal is shorter; the four outer
    // edges go on the stack.
    bool tryFlip(std::uint32_t a, std::uint32_t b, std::vector<std::pair<std::uint32_t, std::uint32_t>>& stack)
    {
        std::uint32_t t;
        int e;
        if (!m_mesh.findEdge(a, b, t, e) || !flippable(t, e))
            return false;
        const std::uint32_t r = m_mesh.triangles[t].v[e];
        const std::uint32_t s = opposite(t, e);
        if (s == kNone || !shorterDiagonal(r, s, a, b))
            return false;
        if (!m_mesh.flip(t, e))
            return false;
        stack.emplace_back(r, a);
        stack.emplace_back(a, s);
        stack.emplace_back(s, b);
        stack.emplace_back(b, r);
        return true;
    }

    void improve()
    {
        std::vector<std::pair<std::uint32_t, std::uint32_t>> stack;
        // A first pass straight over the triangles; what a flip disturbs
        // goes on the stack.
        for (std::uint32_t t = 0; t < m_mesh.triangles.size(); ++t)
            for (int e = 0; e < 3; ++e) {
                const ParamMesh::Triangle& tri = m_mesh.triangles[t];
                if (!tri.alive || tri.neighbour[e] == kNone || tri.neighbour[e] < t || !flippable(t, e))
                    continue;
                const std::uint32_t a = tri.v[(e + 1) % 3], b = tri.v[(e + 2) % 3];
                const std::uint32_t r = tri.v[e], s = opposite(t, e);
                if (s == kNone || !shorterDiagonal(r, s, a, b) || !m_mesh.flip(t, e))
                    continue;
                stack.emplace_back(r, a);
                stack.emplace_back(a, s);
                stack.emplace_back(s, b);
                stack.emplace_back(b, r);
            }
        std::size_t budget = 16 * stack.size() + 16 * m_mesh.triangles.size() + 1024;
        while (!stack.empty() && budget-- > 0) {
            const auto edge = stack.back();
            stack.pop_back();
            tryFlip(edge.first, edge.second, stack);
        }
    }

    // The length of edge (a, b) that is drawn: all of it between two points
    // with images, the part up to where the chord loses its image when one
    // end has none, nothing when neither has (the points without an image
    // form a half-space, nearer than the hither plane).
    double drawnLength(std::uint32_t a, std::uint32_t b) const
    {
        if (m_mapped[a] && m_mapped[b])
            return distance(m_image[a], m_image[b]);
        if (!m_mapped[a] && !m_mapped[b])
            return 0.0;
        const std::uint32_t seen = m_mapped[a] ? a : b;
        const std::uint32_t hidden = m_mapped[a] ? b : a;
        const Point3& p = m_local[seen];
        const Point3& q = m_local[hidden];
        double lo = 0.0, hi = 1.0;
        Point3 last = m_image[seen];
        for (unsigned i = 0; i < kMaxIterations; ++i) {
            const double mid = 0.5 * (lo + hi);
            if (!(lo < mid && mid < hi))
                break;
            const Point3 x{p.x + mid * (q.x - p.x), p.y + mid * (q.y - p.y), p.z + mid * (q.z - p.z)};
            Point3 image;
            if (mapPoint(x, image)) {
                lo = mid;
                last = image;
            } else {
                hi = mid;
            }
        }
        return distance(m_image[seen], last);
    }

    // Flips the edges facing vertex m while the other diagonal is shorter
    // (Lawson's flips, with length in place of the empty-circle test).
    void lawson(std::uint32_t m, std::vector<std::pair<std::uint32_t, std::uint32_t>>& stack)
    {
        stack.clear();
        m_mesh.forEachAround(m, [&](std::uint32_t tri, int corner) {
            const ParamMesh::Triangle& around = m_mesh.triangles[tri];
            stack.emplace_back(around.v[(corner + 1) % 3], around.v[(corner + 2) % 3]);
            return true;
        });
        std::size_t budget = 64;
        std::vector<std::pair<std::uint32_t, std::uint32_t>> outer;
        while (!stack.empty() && budget-- > 0) {
            const auto link = stack.back();
            stack.pop_back();
            outer.clear();
            if (tryFlip(link.first, link.second, outer))
                for (const auto& o : outer)
                    if (o.first != m && o.second != m)
                        stack.push_back(o);
        }
    }

    // Screen space: whether triangle t cannot be seen. Cheap first: its
    // three vertices outside one plane of the view volume; then the convex
    // hull of the surface over its (u, v) bounding box outside that plane
    // (SurfaceHull), which covers the flat triangle too.
    bool hiddenTriangle(std::uint32_t t) const
    {
        const ParamMesh::Triangle& tri = m_mesh.triangles[t];
        unsigned common = 31u;
        double u0 = kInfinity, u1 = -kInfinity, v0 = kInfinity, v1 = -kInfinity;
        for (int k = 0; k < 3; ++k) {
            const Point3& p = m_local[tri.v[k]];
            double values[5];
            m_hull->planes(p.x, p.y, p.z, values);
            for (unsigned plane = 0; plane < 5; ++plane)
                if (!(values[plane] < 0.0))
                    common &= ~(1u << plane);
            const ParamMesh::Vertex& vertex = m_mesh.vertices[tri.v[k]];
            u0 = std::min(u0, vertex.u);
            u1 = std::max(u1, vertex.u);
            v0 = std::min(v0, vertex.v);
            v1 = std::max(v1, vertex.v);
        }
        return common != 0 && m_hull->outside(u0, u1, v0, v1);
    }

    // Whether no triangle on edge (a, b) can be seen (never without a clip).
    bool hiddenEdge(std::uint32_t a, std::uint32_t b) const
    {
        if (!m_hull)
            return false;
        std::uint32_t t;
        int e;
        if (!m_mesh.findEdge(a, b, t, e) && !m_mesh.findEdge(b, a, t, e))
            return false;
        if (!hiddenTriangle(t))
            return false;
        const std::uint32_t n = m_mesh.triangles[t].neighbour[e];
        return n == kNone || hiddenTriangle(n);
    }

    void refine()
    {
        if (!std::isfinite(m_c))
            return;
        struct Long {
            double length;
            std::uint32_t a, b;
            bool operator<(const Long& o) const { return length < o.length; }
        };
        std::priority_queue<Long> heap;
        // Edges that could not be split: not tried again.
        std::set<std::pair<std::uint32_t, std::uint32_t>> failed;
        auto consider = [&](std::uint32_t a, std::uint32_t b) {
            if (failed.count({std::min(a, b), std::max(a, b)}) != 0)
                return;
            const double length = drawnLength(a, b);
            if (length > m_c && !hiddenEdge(a, b))
                heap.push(Long{length, a, b});
        };
        for (std::uint32_t t = 0; t < m_mesh.triangles.size(); ++t) {
            const ParamMesh::Triangle& tri = m_mesh.triangles[t];
            if (!tri.alive)
                continue;
            for (int e = 0; e < 3; ++e) {
                const std::uint32_t n = tri.neighbour[e];
                if (n == kNone || n > t)
                    consider(tri.v[(e + 1) % 3], tri.v[(e + 2) % 3]);
            }
        }
        // A triangle whose third vertex lies within a few key cells of the
        // line of its longest side (nearly collinear vertices, such as the
        // points where edges were split at the hither plane when it cuts the
        // patch along a straight line in (u, v)) blocks the split of an edge
        // it holds: no point of the key grid splits that side into two
        // counterclockwise triangles. Such thin triangles around the edge
        // (those reached from it through thin triangles, a few dozen at
        // most) have their longest side flipped wherever that makes the
        // thinner of the two triangles less thin, until none can be: a
        // strip of collinear vertices is then fanned from the vertices off
        // its line. Each flip raises a minimum height, and flips are counted
        // against a budget proportional to the mesh, so this always ends.
        std::size_t sliverFlips = 0;
        const std::size_t sliverBudget = 4 * m_mesh.triangles.size() + 1024;
        std::vector<std::uint32_t> thin;
        auto height = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
            const double twice = double(m_mesh.orient(a, b, c));
            if (twice <= 0.0)
                return 0.0;
            double longest = 0.0;
            for (const auto& side : {std::make_pair(a, b), std::make_pair(b, c), std::make_pair(c, a)}) {
                const ParamMesh::Vertex& p = m_mesh.vertices[side.first];
                const ParamMesh::Vertex& w = m_mesh.vertices[side.second];
                longest = std::max(longest, std::hypot(double(p.x - w.x), double(p.y - w.y)));
            }
            return twice / longest;
        };
        auto clearSlivers = [&](std::uint32_t a, std::uint32_t b) {
            std::uint32_t t;
            int e;
            if (!m_mesh.findEdge(a, b, t, e) && !m_mesh.findEdge(b, a, t, e))
                return false;
            thin.clear();
            for (const std::uint32_t x : {t, m_mesh.triangles[t].neighbour[e]})
                if (x != kNone)
                    thin.push_back(x);
            for (std::size_t i = 0; i < thin.size() && thin.size() < 64; ++i)
                for (const std::uint32_t n : m_mesh.triangles[thin[i]].neighbour)
                    if (n != kNone && std::find(thin.begin(), thin.end(), n) == thin.end()) {
                        const ParamMesh::Triangle& tri = m_mesh.triangles[n];
                        if (!roomy(tri.v[0], tri.v[1], tri.v[2]))
                            thin.push_back(n);
                    }
            bool changed = false;
            for (bool progress = true; progress && sliverFlips < sliverBudget;) {
                progress = false;
                for (const std::uint32_t x : thin) {
                    const ParamMesh::Triangle& tri = m_mesh.triangles[x];
                    if (!tri.alive || roomy(tri.v[0], tri.v[1], tri.v[2]))
                        continue;
                    int longest = 0;
                    double best = -1.0;
                    for (int k = 0; k < 3; ++k) {
                        const ParamMesh::Vertex& p = m_mesh.vertices[tri.v[(k + 1) % 3]];
                        const ParamMesh::Vertex& w = m_mesh.vertices[tri.v[(k + 2) % 3]];
                        const double length = std::hypot(double(p.x - w.x), double(p.y - w.y));
                        if (length > best) {
                            best = length;
                            longest = k;
                        }
                    }
                    if (!flippable(x, longest))
                        continue;
                    const std::uint32_t p = tri.v[(longest + 1) % 3], w = tri.v[(longest + 2) % 3];
                    const std::uint32_t apex = tri.v[longest], across = opposite(x, longest);
                    const double before = std::min(height(apex, p, w), height(across, w, p));
                    const double after = std::min(height(apex, p, across), height(apex, across, w));
                    if (!(after > before) || !m_mesh.flip(x, longest))
                        continue;
                    ++sliverFlips;
                    changed = progress = true;
                    consider(apex, across);
                    consider(p, apex);
                    consider(apex, w);
                    consider(w, across);
                    consider(across, p);
                }
            }
            return changed;
        };
        std::vector<std::pair<std::uint32_t, std::uint32_t>> stack;
        while (!heap.empty()) {
            const Long edge = heap.top();
            heap.pop();
            std::uint32_t t;
            int e;
            if (failed.count({std::min(edge.a, edge.b), std::max(edge.a, edge.b)}) != 0)
                continue;
            if (!m_mesh.findEdge(edge.a, edge.b, t, e) && !m_mesh.findEdge(edge.b, edge.a, t, e))
                continue;
            if (hiddenEdge(edge.a, edge.b))
                continue;
            if ((m_mesh.triangles[t].constrained >> e) & 1u) {
                m_out.capped = true;
                continue;
            }
            if (m_mesh.aliveCount() + 2 > kMaxTriangles) {
                m_out.capped = true;
                break;
            }
            const ParamMesh::Vertex& va = m_mesh.vertices[edge.a];
            const ParamMesh::Vertex& vb = m_mesh.vertices[edge.b];
            double u = 0.5 * (va.u + vb.u), v = 0.5 * (va.v + vb.v);
            if (m_mapped[edge.a] != m_mapped[edge.b]) {
                // An edge into the part without an image is split where the
                // surface loses its image (its last point with one, found by
                // bisection on the parameters), as curves are: the piece
                // beyond is then drawn with no length, and the piece before
                // is measured as a whole. Halving at the midpoint instead
                // would crowd ever thinner triangles against that edge.
                const ParamMesh::Vertex& seen = m_mapped[edge.a] ? va : vb;
                const ParamMesh::Vertex& hidden = m_mapped[edge.a] ? vb : va;
                double lo = 0.0, hi = 1.0;
                for (unsigned i = 0; i < kMaxIterations; ++i) {
                    const double mid = 0.5 * (lo + hi);
                    if (!(lo < mid && mid < hi))
                        break;
                    Point3 image;
                    const Point3 local = evaluateSurface(m_s, seen.u + mid * (hidden.u - seen.u),
                                                         seen.v + mid * (hidden.v - seen.v));
                    (mapPoint(local, image) ? lo : hi) = mid;
                }
                const double bu = seen.u + lo * (hidden.u - seen.u), bv = seen.v + lo * (hidden.v - seen.v);
                const std::int64_t bx = m_mesh.keyX(bu), by = m_mesh.keyY(bv);
                if (!((bx == va.x && by == va.y) || (bx == vb.x && by == vb.y))) {
                    u = bu;
                    v = bv;
                }
            }
            const std::int64_t x = m_mesh.keyX(u), y = m_mesh.keyY(v);
            if ((x == va.x && y == va.y) || (x == vb.x && y == vb.y)) {
                failed.insert({std::min(edge.a, edge.b), std::max(edge.a, edge.b)});
                m_out.capped = true;
                continue;
            }
            const std::uint32_t c = m_mesh.triangles[t].v[e];
            const std::uint32_t n = m_mesh.triangles[t].neighbour[e];
            const std::uint32_t d = n == kNone ? kNone : opposite(t, e);
            const std::uint32_t m = addMeshVertex(u, v, x, y, evaluateSurface(m_s, u, v));
            const bool splitOk = m_mesh.splitEdge(t, e, m);
            if (!splitOk) {
                // The midpoint (on the key grid) falls outside the edge's two
                // triangles: one of them is a sliver in (u, v), thinner than
                // a key cell. Flipping the edge to its third vertex splits
                // the edge there (only to a shorter diagonal, so flips cannot
                // go round in circles); otherwise the midpoint goes in
                // wherever it lies, and the flips around it take the edge out.
                const std::uint32_t q = m_mesh.triangles[t].v[(e + 1) % 3], r = m_mesh.triangles[t].v[(e + 2) % 3];
                m_mesh.vertices.pop_back();
                if (sliverFlips < sliverBudget && clearSlivers(edge.a, edge.b)) {
                    consider(edge.a, edge.b);
                    continue;
                }
                if (d != kNone && !((m_mesh.triangles[t].fixed >> e) & 1u) && drawnLength(c, d) < edge.length &&
                    roomy(c, q, d) && roomy(c, d, r) && m_mesh.flip(t, e)) {
                    consider(c, d);
                    consider(edge.a, c);
                    consider(c, edge.b);
                    consider(edge.b, d);
                    consider(d, edge.a);
                    continue;
                }
                bool existed = false;
                const ParamMesh::Location where = m_mesh.locate(x, y, t);
                const bool blocked = where.kind == ParamMesh::Location::kOnEdge &&
                                     ((m_mesh.triangles[where.triangle].constrained >> where.index) & 1u);
                const std::uint32_t inserted =
                    blocked ? kNone : m_mesh.insertVertex(u, v, x, y, where.triangle, existed);
                if (inserted == kNone || existed) {
                    failed.insert({std::min(edge.a, edge.b), std::max(edge.a, edge.b)});
                    m_out.capped = true;
                    continue;
                }
                setVertexData(inserted, evaluateSurface(m_s, u, v));
                lawson(inserted, stack);
                m_mesh.forEachAround(inserted, [&](std::uint32_t tri, int corner) {
                    const ParamMesh::Triangle& around = m_mesh.triangles[tri];
                    consider(inserted, around.v[(corner + 1) % 3]);
                    consider(inserted, around.v[(corner + 2) % 3]);
                    consider(around.v[(corner + 1) % 3], around.v[(corner + 2) % 3]);
                    return true;
                });
                consider(edge.a, edge.b);
                continue;
            }
            // Flips around the new vertex, then whatever is still too long.
            lawson(m, stack);
            // Both other corners of every triangle around m: on the boundary
            // the last neighbour appears only as the second.
            m_mesh.forEachAround(m, [&](std::uint32_t tri, int corner) {
                const ParamMesh::Triangle& around = m_mesh.triangles[tri];
                consider(m, around.v[(corner + 1) % 3]);
                consider(m, around.v[(corner + 2) % 3]);
                consider(around.v[(corner + 1) % 3], around.v[(corner + 2) % 3]);
                return true;
            });
        }
    }

    // Merges vertices into neighbours while every edge stays within the
    // bound, shortest edges first: the layout's rows are conservative (their
    // spacing keeps a right-angled cell's diagonal within c1, and the rows
    // follow the worst place along them), so most of the mesh has room.
    void coarsen()
    {
        if (!std::isfinite(m_c))
            return;

        struct Candidate {
            double length;
            std::uint32_t v;
            bool operator<(const Candidate& o) const { return length > o.length; }
        };
        std::priority_queue<Candidate> heap;
        auto shortest = [&](std::uint32_t v) {
            double best = kInfinity;
            m_mesh.forEachAround(v, [&](std::uint32_t t, int c) {
                best = std::min({best, drawnLength(v, m_mesh.triangles[t].v[(c + 1) % 3]),
                                 drawnLength(v, m_mesh.triangles[t].v[(c + 2) % 3])});
                return true;
            });
            return best;
        };
        // Vertices next to a point without an image stay: edges there are
        // measured by their drawn part, which a merge would have to bisect
        // for again and again (and they are few).
        auto alive = [&](std::uint32_t v) {
            const std::uint32_t t = m_mesh.vertices[v].triangle;
            if (t == kNone || !m_mesh.triangles[t].alive || m_mesh.vertices[v].loop >= 0 || !m_mapped[v])
                return false;
            bool seen = true;
            m_mesh.forEachAround(v, [&](std::uint32_t u, int c) {
                seen = m_mapped[m_mesh.triangles[u].v[(c + 1) % 3]] != 0;
                return seen;
            });
            return seen;
        };
        for (std::uint32_t v = 0; v < m_mesh.vertices.size(); ++v)
            if (alive(v))
                heap.push(Candidate{shortest(v), v});
        std::vector<std::uint32_t> link;
        std::vector<std::pair<double, std::uint32_t>> neighbours;
        while (!heap.empty()) {
            const Candidate top = heap.top();
            heap.pop();
            const std::uint32_t v = top.v;
            if (!alive(v))
                continue;
            const double now = shortest(v);
            if (now != top.length) {
                heap.push(Candidate{now, v});
                continue;
            }
            neighbours.clear();
            m_mesh.forEachAround(v, [&](std::uint32_t t, int c) {
                for (int k = 1; k <= 2; ++k) {
                    const std::uint32_t w = m_mesh.triangles[t].v[(c + k) % 3];
                    neighbours.emplace_back(drawnLength(v, w), w);
                }
                return true;
            });
            std::sort(neighbours.begin(), neighbours.end());
            neighbours.erase(std::unique(neighbours.begin(), neighbours.end()), neighbours.end());
            for (const auto& candidate : neighbours) {
                const std::uint32_t w = candidate.second;
                if (!m_mesh.collapsible(v, w, link))
                    continue;
                bool fits = true;
                for (std::uint32_t x : link)
                    if (drawnLength(w, x) > m_c) {
                        fits = false;
                        break;
                    }
                if (!fits)
                    continue;
                m_mesh.collapse(v, w);
                if (alive(w))
                    heap.push(Candidate{shortest(w), w});
                for (std::uint32_t x : link)
                    if (alive(x))
                        heap.push(Candidate{shortest(x), x});
                break;
            }
        }
    }

    // ---- Output -----------------------------------------------------------

    void emit()
    {
        std::vector<std::uint32_t> index(m_mesh.vertices.size(), kNone);
        std::vector<std::uint32_t> order;
        for (const ParamMesh::Triangle& tri : m_mesh.triangles) {
            if (!tri.alive)
                continue;
            for (std::uint32_t v : tri.v) {
                if (index[v] == kNone) {
                    index[v] = std::uint32_t(order.size());
                    order.push_back(v);
                }
                m_out.triangles.push_back(index[v]);
            }
        }
        const std::size_t n = order.size();
        m_out.positions.resize(3 * n);
        m_out.normals.resize(3 * n);
        m_out.uvs.resize(2 * n);
        m_out.parameters.resize(2 * n);
        // Vertices on one row share its collapsed columns.
        std::vector<std::pair<double, std::uint32_t>> keyed(n);
        for (std::uint32_t i = 0; i < n; ++i)
            keyed[i] = {m_mesh.vertices[order[i]].v, i};
        std::sort(keyed.begin(), keyed.end());
        std::vector<std::uint32_t> byV(n);
        for (std::uint32_t i = 0; i < n; ++i)
            byV[i] = keyed[i].second;
        SurfaceRowEvaluator row(m_s);
        for (std::size_t i = 0; i < n;) {
            const double v = m_mesh.vertices[order[byV[i]]].v;
            std::size_t j = i;
            while (j < n && m_mesh.vertices[order[byV[j]]].v == v)
                ++j;
            const bool shared = j - i >= 8;
            if (shared)
                row.setV(v, true);
            for (; i < j; ++i) {
                const ParamMesh::Vertex& vertex = m_mesh.vertices[order[byV[i]]];
                const SurfacePoint p = shared ? row.pointWithNormal(vertex.u) : evaluateWithNormal(m_s, vertex.u, v);
                writeVertex(byV[i], p, vertex.u, v);
            }
        }
    }

    const PatchRef& m_patch;
    SurfaceRef m_s;
    const TessellationOptions& m_how;
    PointMapping m_mapping; // customMapping, or the projective mapping
    TessellatedSurface& m_out;
    SurfaceDomain m_domain;
    std::vector<Span> m_uSpans;
    std::vector<Span> m_vSpans;
    SurfaceRowEvaluator m_iso;

    bool m_adaptive = false;
    double m_c = kInfinity;
    std::uint32_t m_uSegments = 1;
    std::uint32_t m_vSegments = 1;
    bool m_gridRows = false;
    std::size_t m_vertexBudget = std::numeric_limits<std::size_t>::max();
    std::size_t m_layoutVertices = 0;
    std::size_t m_lastRowSize = 0;
    std::vector<double> m_halfway;
    double m_vProgress = 0.0;

    std::vector<std::vector<TrimVertex>> m_loops;
    std::vector<bool> m_ccw;
    std::vector<Constraint> m_constraints;
    bool m_trimmed = false;

    std::optional<SurfaceHull> m_hull;
    bool m_culling = false;
    std::vector<double> m_uCuts;
    std::vector<double> m_vCuts;
    std::size_t m_cellColumns = 0;
    std::vector<std::uint8_t> m_hiddenCells;
    ParamMesh m_mesh;
    std::vector<Point3> m_local;
    std::vector<Point3> m_image;
    std::vector<std::uint8_t> m_mapped;
};

} // namespace

void tessellateSurface(const PatchRef& patch, const TessellationOptions& how, TessellatedSurface& out)
{
    // The arrays are replaced by Tessellator::run (emptied, or overwritten in place).
    out.substituted = false;
    out.effectiveValue = 0.0;
    out.uSegments = out.vSegments = 0;
    out.capped = false;
    out.crossing = false;
    out.crossingLoop = out.crossingOther = 0;
    out.crossingU = out.crossingV = 0.0;
    Tessellator(patch, how, out).run();
    if (out.crossing) {
        out.positions.clear();
        out.normals.clear();
        out.uvs.clear();
        out.parameters.clear();
        out.triangles.clear();
    }
}

} // namespace q3::nurbs
