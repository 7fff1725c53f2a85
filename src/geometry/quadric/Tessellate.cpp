// SPDX-License-Identifier: MIT
// Copyright (c) 2026 The Q3 authors

// Rows, stitched (Tessellate.h gives the scheme). Why each step:
//   - Rows along u at fixed v suit every patch of Shapes.h: u is the angle
//     around (or a straight direction), v runs between the patch's boundary
//     curves, which are the rows a linked patch shares.
//   - A row's points are uniform in u or derived from its neighbour's, not
//     marched point by point: rows staggered by half a step give triangles
//     close to equilateral, the shape with the most area for a bounded edge
//     (an equilateral triangle of side c1 has area sqrt(3)/4 c1^2, the lower
//     bound the tests measure against). Uniform rows suit rows of similar
//     length; derived rows keep the stagger where rows grow fast.
//   - Stitching in parameter order (the shorter diagonal only between
//     nearly aligned points; a variant of the greedy rule of Fuchs, Kedem,
//     Uselton, "Optimal surface reconstruction from planar contours", CACM
//     1977) never crosses itself, also where a view foreshortens the
//     surface so much that the shorter drawn diagonal would reach across
//     its neighbours; as two rows draw together, its new edges tend to the
//     rows' own chords, all below kRowChord c1, so halving a strip with a
//     long edge ends, and the edge guarantee holds.

#include "geometry/quadric/Tessellate.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>

namespace q3::quadric {

namespace {

/// Thrown when an attempt would exceed maxTriangles; tessellate() retries
/// coarser.
struct OverBudget {};

bool isFinite(const Vec3& p)
{
    return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}

/// A local point and its image in the measured space.
struct Image {
    Vec3 local{0.0};
    Vec3 mapped{0.0};
    bool has = false;
};

/// Lengths as drawn: through the mapping (measured), or in local space
/// (constant, where only the stitching's shorter diagonal uses them).
class Measure {
public:
    explicit Measure(const Mapping* map) : m_map(map) {}

    Image image(const Vec3& local) const
    {
        Image result;
        result.local = local;
        if (m_map == nullptr) {
            result.mapped = local;
            result.has = true;
        } else {
            result.has = (*m_map)(local, result.mapped) && isFinite(result.mapped);
        }
        return result;
    }

    /// The drawn length of the straight edge a-b (Tessellate.h).
    double length(const Image& a, const Image& b) const
    {
        if (a.has && b.has)
            return glm::distance(a.mapped, b.mapped);
        if (!a.has && !b.has)
            return 0.0;
        const Image& in = a.has ? a : b;
        const Image& out = a.has ? b : a;
        // The points with an image form a half-space, so along the edge
        // they are an interval starting at `in`.
        double lo = 0.0, hi = 1.0;
        Vec3 reached = in.mapped;
        for (int i = 0; i < 48 && hi - lo > 1e-12; ++i) {
            const double mid = 0.5 * (lo + hi);
            const Image probe = image(in.local + mid * (out.local - in.local));
            if (probe.has) {
                lo = mid;
                reached = probe.mapped;
            } else {
                hi = mid;
            }
        }
        return glm::distance(in.mapped, reached);
    }

private:
    const Mapping* m_map;
};

/// How a measured patch's rows get their points (Tessellate.h): each row on
/// its own, uniform, alternate rows offset by half a step (best where
/// neighbouring rows are alike: cylinders, spheres, cones); or each row
/// derived from its neighbour (best where rows grow fast: disks, tori); or,
/// for a disk-like patch closing a curved edge (a cap, a torus's
/// cross-section: collapsed at v0, its v1 row given), every row on the rays
/// of the given one (every other ray where the row has shrunk enough): rows
/// on shared rays nest, so no triangle can fold however coarse the given row
/// is where the view squeezes it.
enum class Strategy { kUniform, kDerived, kAligned };

/// What an attempt works with.
struct Setting {
    Method method = Method::kConstant;
    double c1 = 1.0, c2 = 1.0; ///< constant counts, or c1 the edge bound
    std::size_t maxTriangles = 0;
    Measure measure{nullptr};

    double rowChord() const { return kRowChord * c1; }
    double rowSpacing(Strategy strategy) const
    {
        return (strategy == Strategy::kDerived ? kDerivedRowSpacing : kRowSpacing) * c1;
    }
};

unsigned constantCount(const ConstantRule& rule, const Setting& s)
{
    if (rule.which == 0)
        return std::max(1u, rule.minimum);
    const double c = rule.which == 1 ? s.c1 : s.c2;
    const double wanted = std::ceil(c * rule.span - 1e-9);
    return unsigned(std::clamp(wanted, double(rule.minimum), 1e9));
}

/// A patch's rows once tessellated, for the patches linked to it.
struct PatchRows {
    std::vector<double> values; ///< every row's v, increasing
    std::vector<double> first;  ///< the u parameters of the v0 row
    std::vector<double> last;   ///< and of the v1 row
};

struct Row {
    double v = 0.0;
    bool collapsed = false;
    int phase = 0;                    ///< uniform rows: 1 when offset by half a step
    std::vector<double> u;            ///< empty when collapsed
    std::vector<Image> images;        ///< one per u (one when collapsed)
    std::vector<std::uint32_t> index; ///< output vertices (none when collapsed)
};

/// One triangle corner before it is committed: a row's point, or the
/// collapsed row's point at parameter apexU (its own vertex).
struct Corner {
    const Row* row;
    std::size_t j;
    double apexU;
};

/// Uniform parameters across [u0, u1]: n segments, or with phase 1 the same
/// steps offset by half (two half steps at the ends).
std::vector<double> uniform(double u0, double u1, unsigned n, int phase = 0)
{
    std::vector<double> u;
    const double step = (u1 - u0) / n;
    if (phase == 0) {
        for (unsigned i = 0; i <= n; ++i)
            u.push_back(i == n ? u1 : u0 + i * step);
        return u;
    }
    u.push_back(u0);
    for (unsigned i = 0; i < n; ++i)
        u.push_back(u0 + (i + 0.5) * step);
    u.push_back(u1);
    return u;
}

class PatchBuilder {
public:
    PatchBuilder(const Patch& patch, const Setting& setting, Strategy strategy, std::size_t budget, Tessellation& out,
                 const std::vector<PatchRows>& done)
        : m_patch(patch), m_s(setting), m_strategy(strategy), m_budget(budget), m_out(out), m_done(done)
    {
        m_flip = reversed();
    }

    PatchRows build()
    {
        const std::vector<double> values = rowValues();
        const std::size_t last = values.size() - 1;
        // Rows are derived from a neighbour, starting from the shortest and
        // growing towards the longest (the pivot) from both ends: growing
        // rows only split segments, which keeps the stagger.
        std::size_t pivot = last;
        if (m_strategy == Strategy::kAligned) {
            pivot = 0;
        } else if (m_s.method == Method::kMeasured && m_strategy == Strategy::kDerived) {
            double longest = -1.0;
            for (std::size_t k = 0; k <= last; ++k) {
                const double length = rowLength(values[k]);
                if (length > longest) {
                    longest = length;
                    pivot = k;
                }
            }
        }
        std::deque<Row> rows(last + 1);
        auto build = [&](std::size_t k, const Row* from) {
            const bool collapsed = (k == 0 && m_patch.collapsedV0) || (k == last && m_patch.collapsedV1);
            const RowSource* source = k == 0 ? &m_patch.link.first : k == last ? &m_patch.link.last : nullptr;
            rows[k] = makeRow(values[k], collapsed, source, from, int(k % 2));
        };
        for (std::size_t k = 0; k <= pivot; ++k)
            build(k, k > 0 ? &rows[k - 1] : nullptr);
        for (std::size_t k = last; k > pivot; --k)
            build(k, k < last ? &rows[k + 1] : nullptr);
        for (std::size_t k = 0; k < last; ++k)
            stitch(rows[k], rows[k + 1], 0);

        PatchRows result;
        for (const Row& row : rows)
            result.values.push_back(row.v);
        for (const Row& row : m_inserted)
            result.values.push_back(row.v);
        std::sort(result.values.begin(), result.values.end());
        result.first = rows.front().u;
        result.last = rows.back().u;
        return result;
    }

private:
    // ---- Orientation -------------------------------------------------------

    /// True when counterclockwise in (u, v) faces inwards: the parameter
    /// cross product at the patch's centre against its normal there.
    bool reversed() const
    {
        const Patch& p = m_patch;
        const double u = 0.5 * (p.u0 + p.u1), v = 0.5 * (p.v0 + p.v1);
        const double du = 1e-4 * (p.u1 - p.u0), dv = 1e-4 * (p.v1 - p.v0);
        const Vec3 pu = p.point(u + du, v) - p.point(u - du, v);
        const Vec3 pv = p.point(u, v + dv) - p.point(u, v - dv);
        return glm::dot(glm::cross(pu, pv), p.normal(u, v)) < 0.0;
    }

    // ---- Rows --------------------------------------------------------------

    /// The fewest segments a row (along u) and the rows (along v) may have:
    /// 3 around a full turn, and with the measured method one per quarter
    /// turn (Patch::turnsU); the constant method's counts are the user's.
    unsigned minimumAlongU() const { return minimum(m_patch.closedU ? 3u : 1u, m_patch.turnsU); }
    unsigned minimumAlongV() const
    {
        const unsigned base = m_patch.closedV ? 3u : m_patch.collapsedV0 && m_patch.collapsedV1 ? 2u : 1u;
        return minimum(base, m_patch.turnsV);
    }
    unsigned minimum(unsigned base, double turns) const
    {
        if (m_s.method == Method::kConstant)
            return base;
        return std::max(base, unsigned(std::ceil(4.0 * turns - 1e-9)));
    }

    std::vector<double> rowValues()
    {
        const Patch& p = m_patch;
        if (p.link.rows >= 0)
            return m_done[std::size_t(p.link.rows)].values;
        unsigned n = 0;
        if (m_s.method == Method::kConstant) {
            n = std::max(constantCount(p.constantV, m_s), minimumAlongV());
        } else {
            std::vector<double> marched = march();
            if (marched.size() - 1 >= minimumAlongV())
                return marched;
            n = minimumAlongV();
        }
        return uniform(p.v0, p.v1, n);
    }

    std::vector<Image> probeRow(double v) const
    {
        std::vector<Image> images;
        for (int j = 0; j <= kProbes; ++j)
            images.push_back(image(m_patch.u0 + (m_patch.u1 - m_patch.u0) * j / kProbes, v));
        return images;
    }

    Image image(double u, double v) const { return m_s.measure.image(m_patch.point(u, v)); }

    /// v values from v0 to v1, each step as long as keeps the drawn distance
    /// between the rows at the probes within [0.9, 1] kRowSpacing c1.
    std::vector<double> march() const
    {
        const Patch& p = m_patch;
        const double h = m_s.rowSpacing(m_strategy);
        std::vector<double> values{p.v0};
        std::vector<Image> from = probeRow(p.v0);
        double v = p.v0;
        double guess = (p.v1 - p.v0) / 8;
        const double longestStep = (p.v1 - p.v0) / minimumAlongV();
        while (v < p.v1) {
            const double remaining = std::min(p.v1 - v, longestStep);
            double step = std::min(guess, remaining);
            double lo = 0.0, hi = 0.0; // largest step known to fit, smallest known not to
            std::vector<Image> loRow;
            for (int iteration = 0; iteration < 40; ++iteration) {
                std::vector<Image> to = probeRow(v + step);
                const double widest = spacing(from, to);
                if (widest <= h) {
                    lo = step;
                    loRow = std::move(to);
                    if (step >= remaining || widest >= 0.9 * h)
                        break;
                    step = hi > 0.0 ? 0.5 * (lo + hi)
                                    : std::min(remaining, step * std::min(4.0, widest > 0.0 ? 0.95 * h / widest : 4.0));
                } else {
                    hi = step;
                    step = lo > 0.0 ? 0.5 * (lo + hi) : step * std::clamp(0.95 * h / widest, 0.05, 0.9);
                }
            }
            if (lo == 0.0) {
                // No step fitted (a mapping too steep to resolve here): take
                // the last one tried; the strip check refines around it.
                lo = step;
                loRow = probeRow(v + step);
            }
            v = lo >= p.v1 - v ? p.v1 : v + lo;
            values.push_back(v);
            from = std::move(loRow);
            guess = lo;
            if (values.size() > m_s.maxTriangles)
                throw OverBudget{};
        }
        return values;
    }

    /// The largest distance between two probed rows: at each probe, the
    /// part of the step between them across the first row's direction there
    /// (a row's points slide along it when they are staggered, so a skewed
    /// parameterisation does not bring rows closer than they need be).
    double spacing(const std::vector<Image>& from, const std::vector<Image>& to) const
    {
        double widest = 0.0;
        for (std::size_t j = 0; j < from.size(); ++j) {
            double d = m_s.measure.length(from[j], to[j]);
            const std::size_t before = j == 0 ? 0 : j - 1, after = std::min(j + 1, from.size() - 1);
            if (d > 0.0 && from[j].has && to[j].has && from[before].has && from[after].has) {
                const Vec3 along = from[after].mapped - from[before].mapped;
                const double length = glm::length(along);
                if (length > 0.0) {
                    const Vec3 step = to[j].mapped - from[j].mapped;
                    const Vec3 across = step - (glm::dot(step, along) / (length * length)) * along;
                    d = glm::length(across);
                }
            }
            widest = std::max(widest, d);
        }
        return widest;
    }

    const std::vector<double>* sourced(const RowSource* source) const
    {
        if (source == nullptr || source->patch < 0)
            return nullptr;
        const PatchRows& rows = m_done[std::size_t(source->patch)];
        switch (source->what) {
        case RowSource::kFirstRow:
            return &rows.first;
        case RowSource::kLastRow:
            return &rows.last;
        case RowSource::kRowValues:
            return &rows.values;
        }
        return nullptr;
    }

    /// The drawn length of the row at v, over the probes.
    double rowLength(double v) const
    {
        const std::vector<Image> probes = probeRow(v);
        double length = 0.0;
        for (int j = 0; j < kProbes; ++j)
            length += m_s.measure.length(probes[std::size_t(j)], probes[std::size_t(j) + 1]);
        return length;
    }

    /// A row at v: one point when collapsed; the u parameters a linked
    /// patch gives; uniform (constant method); derived from the neighbouring
    /// row `from`; or, with none, uniform as sparse as the chord bound
    /// allows.
    Row makeRow(double v, bool collapsed, const RowSource* source, const Row* from, int phase)
    {
        Row row;
        row.v = v;
        row.collapsed = collapsed;
        row.phase = phase;
        if (collapsed) {
            row.images.push_back(image(0.5 * (m_patch.u0 + m_patch.u1), v));
            return row;
        }
        if (const std::vector<double>* given = sourced(source)) {
            row.u = *given;
            for (double u : row.u)
                row.images.push_back(image(u, v));
        } else if (m_s.method == Method::kConstant) {
            row.u = uniform(m_patch.u0, m_patch.u1, std::max(constantCount(m_patch.constantU, m_s), minimumAlongU()));
            for (double u : row.u)
                row.images.push_back(image(u, v));
        } else if (m_strategy == Strategy::kAligned && from != nullptr && !from->collapsed) {
            alignedRow(row, *from);
        } else if (m_strategy == Strategy::kDerived && from != nullptr && !from->collapsed) {
            derivedRow(row, *from);
        } else if (m_strategy == Strategy::kDerived) {
            marchedRow(row);
        } else {
            freshRow(row);
        }
        m_used += row.u.size();
        if (m_used > 2 * m_budget + 64)
            throw OverBudget{};
        for (std::size_t j = 0; j < row.u.size(); ++j)
            row.index.push_back(emit(row.u[j], v, row.images[j].local));
        return row;
    }

    /// The fewest uniform points that keep every chord of the row within
    /// kRowChord c1.
    void freshRow(Row& row) const
    {
        const Patch& p = m_patch;
        const double w = m_s.rowChord();
        const std::vector<Image> probes = probeRow(row.v);
        double widest = 0.0;
        for (int j = 0; j < kProbes; ++j)
            widest = std::max(widest, m_s.measure.length(probes[std::size_t(j)], probes[std::size_t(j) + 1]));
        double estimate = std::ceil(widest * kProbes / w);
        for (int iteration = 0;; ++iteration) {
            if (!(estimate <= double(m_s.maxTriangles)))
                throw OverBudget{};
            const unsigned n = std::max(unsigned(estimate), minimumAlongU());
            row.u = uniform(p.u0, p.u1, n, row.phase);
            row.images.clear();
            for (double u : row.u)
                row.images.push_back(image(u, row.v));
            double longest = 0.0;
            for (std::size_t j = 0; j + 1 < row.images.size(); ++j)
                longest = std::max(longest, m_s.measure.length(row.images[j], row.images[j + 1]));
            if (longest <= w || iteration >= 60)
                return;
            estimate = std::max(double(n) + 1.0, std::ceil(n * longest / w * 1.02));
        }
    }

    /// The rays of `from` (the next row outwards), every other one dropped
    /// where this row's chords and spans still allow it. A row on a subset of
    /// the rays of the row outside it lies inside it (each chord a scaled
    /// copy of one inside the outer row), so no triangle between them folds.
    void alignedRow(Row& row, const Row& from) const
    {
        const double w = m_s.rowChord();
        const double widest = (m_patch.u1 - m_patch.u0) / minimumAlongU();
        std::vector<Image> images;
        for (double u : from.u)
            images.push_back(image(u, row.v));
        const std::size_t n = from.u.size();
        bool halve = n > 2 && (n - 1) % 2 == 0 && (n - 1) / 2 >= minimumAlongU();
        for (std::size_t j = 0; halve && j + 2 < n; j += 2)
            halve = m_s.measure.length(images[j], images[j + 2]) <= w && from.u[j + 2] - from.u[j] <= widest;
        row.u.clear();
        row.images.clear();
        for (std::size_t j = 0; j < n; j += halve ? 2 : 1) {
            row.u.push_back(from.u[j]);
            row.images.push_back(images[j]);
        }
    }

    /// A row marched along u: each point as far from the last as keeps the
    /// chord within kRowChord c1 (probes of 1/kProbes of a segment's
    /// longest allowed span, then bisection), so that a row whose speed
    /// varies gets its points where they are needed.
    void marchedRow(Row& row) const
    {
        const Patch& p = m_patch;
        const double w = m_s.rowChord();
        const double widest = (p.u1 - p.u0) / minimumAlongU();
        const double probe = widest / kProbes;
        row.u.assign(1, p.u0);
        row.images.assign(1, image(p.u0, row.v));
        while (row.u.back() < p.u1) {
            const double start = row.u.back();
            const double limit = std::min(p.u1, start + widest);
            double inside = start, outside = -1.0;
            Image insideImage = row.images.back();
            for (double next = std::min(limit, start + probe);; next = std::min(limit, next + probe)) {
                const Image at = image(next, row.v);
                if (m_s.measure.length(row.images.back(), at) > w) {
                    outside = next;
                    break;
                }
                inside = next;
                insideImage = at;
                if (next >= limit)
                    break;
            }
            if (outside > 0.0) {
                for (int i = 0; i < 30; ++i) {
                    const double mid = 0.5 * (inside + outside);
                    const Image at = image(mid, row.v);
                    if (m_s.measure.length(row.images.back(), at) > w) {
                        outside = mid;
                    } else {
                        inside = mid;
                        insideImage = at;
                    }
                }
                if (inside <= start) {
                    inside = outside;
                    insideImage = image(inside, row.v);
                }
            }
            row.u.push_back(inside >= p.u1 ? p.u1 : inside);
            row.images.push_back(inside >= p.u1 ? image(p.u1, row.v) : insideImage);
            if (row.u.size() > m_budget + 1)
                throw OverBudget{};
        }
    }

    /// The row staggered against `from`: a point above the middle of each of
    /// its segments (and the ends); then every chord longer than kRowChord c1
    /// split in the middle, and the longest chords split (or, where the row
    /// contracts, the points with the shortest chords around them dropped)
    /// until the average chord is about kRowAverage kRowChord c1. Choosing
    /// the longest spreads the new points over the rows as the row grows,
    /// where splitting only what must be split would split every chord of a
    /// uniformly growing row at once and halve them all.
    void derivedRow(Row& row, const Row& from) const
    {
        const double w = m_s.rowChord();
        std::vector<double> u{m_patch.u0};
        std::vector<Image> images{image(m_patch.u0, row.v)};
        for (std::size_t j = 0; j + 1 < from.u.size(); ++j) {
            u.push_back(0.5 * (from.u[j] + from.u[j + 1]));
            images.push_back(image(u.back(), row.v));
            apex(from, j, row.v, u.back(), images.back());
        }
        u.push_back(m_patch.u1);
        images.push_back(image(m_patch.u1, row.v));
        std::vector<double> chords;
        for (std::size_t j = 0; j + 1 < u.size(); ++j)
            chords.push_back(m_s.measure.length(images[j], images[j + 1]));
        double total = 0.0;
        for (double c : chords)
            total += c;
        const double target = std::max(double(minimumAlongU()), std::ceil(total / (kRowAverage * w)));
        if (!(target <= double(m_s.maxTriangles)))
            throw OverBudget{};

        // Splits: every chord above w, then the longest (ties broken by a
        // scrambled position, so that equal chords split evenly along the
        // row) while the row is short of the target.
        std::vector<bool> split(chords.size(), false);
        std::size_t count = chords.size();
        const double widest = (m_patch.u1 - m_patch.u0) / minimumAlongU();
        for (std::size_t j = 0; j < chords.size(); ++j)
            if (chords[j] > w || u[j + 1] - u[j] > widest) {
                split[j] = true;
                ++count;
            }
        if (double(count) < target) {
            std::vector<std::pair<double, std::size_t>> order;
            for (std::size_t j = 0; j < chords.size(); ++j)
                if (!split[j])
                    order.emplace_back(chords[j] * (1.0 + 1e-9 * scramble(j)), j);
            std::sort(order.begin(), order.end(), std::greater<>());
            for (std::size_t k = 0; k < order.size() && double(count) < target; ++k) {
                split[order[k].second] = true;
                ++count;
            }
        }
        std::vector<double> splitU{u[0]};
        std::vector<Image> splitImages{images[0]};
        for (std::size_t j = 0; j + 1 < u.size(); ++j) {
            if (split[j])
                splitInto(splitU, splitImages, u[j], images[j], u[j + 1], images[j + 1], row.v, 0);
            splitU.push_back(u[j + 1]);
            splitImages.push_back(images[j + 1]);
        }
        if (splitU.size() > m_s.maxTriangles)
            throw OverBudget{};

        // Drops, where the row is locally much denser than it needs be (its
        // metric shrank, or a neighbour's split left short chords): the
        // points whose two chords together are shortest and at most
        // kRowDrop w, never two neighbours nor a point just split in.
        const std::size_t n = splitU.size();
        std::vector<bool> drop(n, false);
        std::vector<bool> fresh(n, false);
        for (std::size_t j = 1, k = 1; j < n && k < u.size(); ++j) {
            if (splitU[j] == u[k])
                ++k;
            else
                fresh[j] = true;
        }
        {
            std::vector<std::pair<double, std::size_t>> order;
            for (std::size_t j = 1; j + 1 < n; ++j) {
                if (fresh[j])
                    continue;
                const double merged = m_s.measure.length(splitImages[j - 1], splitImages[j + 1]);
                if (merged <= kRowDrop * w && splitU[j + 1] - splitU[j - 1] <= widest)
                    order.emplace_back(merged * (1.0 + 1e-9 * scramble(j)), j);
            }
            std::sort(order.begin(), order.end());
            std::size_t segments = n - 1;
            for (const auto& [merged, j] : order) {
                if (segments <= minimumAlongU())
                    break;
                if (drop[j - 1] || drop[j + 1])
                    continue;
                drop[j] = true;
                --segments;
            }
        }
        row.u.clear();
        row.images.clear();
        for (std::size_t j = 0; j < n; ++j)
            if (!drop[j]) {
                row.u.push_back(splitU[j]);
                row.images.push_back(splitImages[j]);
            }
    }

    /// Moves the point (u, image) above segment j of row `from` along its
    /// row to where it is as far from both ends of the segment (regula
    /// falsi on the difference of the squared distances, within the
    /// segment): the triangle on the segment is isosceles even where the
    /// parameterisation is skewed.
    void apex(const Row& from, std::size_t j, double v, double& u, Image& at) const
    {
        const Image& left = from.images[j];
        const Image& right = from.images[j + 1];
        if (!left.has || !right.has || !at.has)
            return;
        auto balance = [&](const Image& p) {
            const Vec3 a = p.mapped - left.mapped, b = p.mapped - right.mapped;
            return glm::dot(a, a) - glm::dot(b, b);
        };
        // Within the middle half of the segment, so the row stays spread out
        // even where the metric is strongly anisotropic.
        const double quarter = 0.25 * (from.u[j + 1] - from.u[j]);
        double lo = from.u[j] + quarter, hi = from.u[j + 1] - quarter;
        Image loImage = image(lo, v), hiImage = image(hi, v);
        if (!loImage.has || !hiImage.has)
            return;
        double fLo = balance(loImage), fHi = balance(hiImage);
        if (!(fLo < 0.0 && fHi > 0.0))
            return;
        for (int iteration = 0; iteration < 8; ++iteration) {
            const double t = lo + (hi - lo) * fLo / (fLo - fHi);
            const Image probe = image(t, v);
            if (!probe.has)
                return;
            const double f = balance(probe);
            u = t;
            at = probe;
            if (std::fabs(f) <= 1e-6 * (std::fabs(fLo) + std::fabs(fHi)))
                return;
            if (f < 0.0) {
                lo = t;
                fLo = f;
            } else {
                hi = t;
                fHi = f;
            }
        }
    }

    /// Appends the points splitting the chord a-b (parameters ua, ub) in the
    /// middle, recursively while a half is longer than kRowChord c1.
    void splitInto(std::vector<double>& u, std::vector<Image>& images, double ua, const Image& a, double ub,
                   const Image& b, double v, int depth) const
    {
        const double mid = 0.5 * (ua + ub);
        const Image m = image(mid, v);
        const double w = m_s.rowChord();
        const double widest = (m_patch.u1 - m_patch.u0) / minimumAlongU();
        const bool deeper = depth < 48 && u.size() < m_s.maxTriangles;
        if (deeper && (m_s.measure.length(a, m) > w || mid - ua > widest))
            splitInto(u, images, ua, a, mid, m, v, depth + 1);
        u.push_back(mid);
        images.push_back(m);
        if (deeper && (m_s.measure.length(m, b) > w || ub - mid > widest))
            splitInto(u, images, mid, m, ub, b, v, depth + 1);
    }

    /// A fixed scrambling of indices into [0, 1) (the golden ratio's
    /// fractional multiples): equal chords are taken in an order spread
    /// along the row.
    static double scramble(std::size_t j)
    {
        const double x = double(j) * 0.6180339887498949;
        return x - std::floor(x);
    }

    std::uint32_t emit(double u, double v, const Vec3& point)
    {
        m_out.positions.push_back(point);
        m_out.normals.push_back(m_patch.normal(u, v));
        m_out.uvs.push_back(m_patch.uv(u, v));
        m_out.parts.push_back(m_patch.part);
        return std::uint32_t(m_out.positions.size() - 1);
    }

    // ---- Strips ------------------------------------------------------------

    const Image& imageOf(const Corner& c) const { return c.row->collapsed ? c.row->images[0] : c.row->images[c.j]; }

    double length(const Corner& a, const Corner& b) const { return m_s.measure.length(imageOf(a), imageOf(b)); }

    /// Stitches rows a (lower v) and b; halves the strip while an edge is
    /// longer than c1 (measured method).
    void stitch(const Row& a, const Row& b, int depth)
    {
        if (a.collapsed && b.collapsed)
            return;
        std::vector<Corner> corners;
        auto triangle = [&](const Corner& x, const Corner& y, const Corner& z) {
            corners.insert(corners.end(), {x, y, z});
        };
        auto at = [](const Row& row, std::size_t j) { return Corner{&row, j, 0.0}; };
        auto apex = [](const Row& row, const Row& other, std::size_t j) {
            return Corner{&row, 0, 0.5 * (other.u[j] + other.u[j + 1])};
        };
        if (a.collapsed) {
            for (std::size_t j = 0; j + 1 < b.u.size(); ++j)
                triangle(apex(a, b, j), at(b, j + 1), at(b, j));
        } else if (b.collapsed) {
            for (std::size_t j = 0; j + 1 < a.u.size(); ++j)
                triangle(at(a, j), at(a, j + 1), apex(b, a, j));
        } else {
            const std::size_t p = a.u.size() - 1, q = b.u.size() - 1;
            std::size_t i = 0, j = 0;
            while (i < p || j < q) {
                bool advanceA = j == q;
                if (i < p && j < q) {
                    // In parameter order, so that no triangle reaches across
                    // its neighbours (a shorter diagonal in a foreshortened
                    // view can be a fold); where the next points are within
                    // a third of a segment of each other, the shorter
                    // diagonal.
                    const double gap = a.u[i + 1] - b.u[j + 1];
                    const double near = 0.35 * std::min(a.u[i + 1] - a.u[i], b.u[j + 1] - b.u[j]);
                    advanceA = gap <= 0.0;
                    if (std::fabs(gap) <= near) {
                        const double viaA = length(at(a, i + 1), at(b, j));
                        const double viaB = length(at(a, i), at(b, j + 1));
                        advanceA = viaA < viaB || (viaA == viaB && gap <= 0.0);
                    }
                }
                if (i < p && j < q) {
                    // Never a fold where the other choice is none (a sparse
                    // row against a dense one in a strongly curved or
                    // anisotropic part).
                    const bool foldA = folds(at(a, i), at(a, i + 1), at(b, j));
                    const bool foldB = folds(at(a, i), at(b, j + 1), at(b, j));
                    if (advanceA && foldA && !foldB)
                        advanceA = false;
                    else if (!advanceA && foldB && !foldA)
                        advanceA = true;
                }
                if (advanceA) {
                    triangle(at(a, i), at(a, i + 1), at(b, j));
                    ++i;
                } else {
                    triangle(at(a, i), at(b, j + 1), at(b, j));
                    ++j;
                }
            }
        }

        if (m_s.method == Method::kMeasured && tooLong(corners)) {
            if (depth < kMaxRefinement) {
                const Row* from = a.collapsed || m_strategy == Strategy::kAligned ? &b : &a;
                const Row& middle =
                    m_inserted.emplace_back(makeRow(0.5 * (a.v + b.v), false, nullptr, from, 1 - a.phase));
                stitch(a, middle, depth + 1);
                stitch(middle, b, depth + 1);
                return;
            }
            ++m_out.unresolved;
        }
        commit(corners);
    }

    /// True when the triangle x y z (counterclockwise in parameters) faces
    /// against the patch's outward normal at its centre.
    bool folds(const Corner& x, const Corner& y, const Corner& z) const
    {
        const Vec3& px = imageOf(x).local;
        const Vec3& py = imageOf(y).local;
        const Vec3& pz = imageOf(z).local;
        auto param = [](const Corner& c) { return c.row->collapsed ? c.apexU : c.row->u[c.j]; };
        const double u = (param(x) + param(y) + param(z)) / 3.0;
        const double v = (x.row->v + y.row->v + z.row->v) / 3.0;
        const double facing = glm::dot(glm::cross(py - px, pz - px), m_patch.normal(u, v));
        return m_flip ? facing > 0.0 : facing < 0.0;
    }

    bool tooLong(const std::vector<Corner>& corners) const
    {
        for (std::size_t t = 0; t < corners.size(); t += 3)
            for (int k = 0; k < 3; ++k)
                if (length(corners[t + std::size_t(k)], corners[t + std::size_t(k + 1) % 3]) > m_s.c1)
                    return true;
        return false;
    }

    void commit(const std::vector<Corner>& corners)
    {
        if (m_out.triangleCount() + corners.size() / 3 > m_budget)
            throw OverBudget{};
        for (std::size_t t = 0; t < corners.size(); t += 3) {
            std::uint32_t index[3];
            for (int k = 0; k < 3; ++k) {
                const Corner& c = corners[t + std::size_t(k)];
                index[k] =
                    c.row->collapsed ? emit(c.apexU, c.row->v, m_patch.point(c.apexU, c.row->v)) : c.row->index[c.j];
            }
            if (m_flip)
                std::swap(index[1], index[2]);
            m_out.triangles.insert(m_out.triangles.end(), {index[0], index[1], index[2]});
        }
    }

    const Patch& m_patch;
    const Setting& m_s;
    Strategy m_strategy;
    std::size_t m_budget; // the most triangles this patch may have
    Tessellation& m_out;
    const std::vector<PatchRows>& m_done;
    std::size_t m_used = 0;     // row points made
    std::deque<Row> m_inserted; // rows added by halving strips (stable addresses)
    bool m_flip = false;
};

/// Appends `part` to `out`.
void append(Tessellation& out, const Tessellation& part)
{
    const std::uint32_t base = std::uint32_t(out.positions.size());
    out.positions.insert(out.positions.end(), part.positions.begin(), part.positions.end());
    out.normals.insert(out.normals.end(), part.normals.begin(), part.normals.end());
    out.uvs.insert(out.uvs.end(), part.uvs.begin(), part.uvs.end());
    out.parts.insert(out.parts.end(), part.parts.begin(), part.parts.end());
    for (std::uint32_t index : part.triangles)
        out.triangles.push_back(base + index);
    out.unresolved += part.unresolved;
}

/// One attempt at the whole shape; throws OverBudget. The measured method
/// builds each patch with both strategies and keeps the one with fewer
/// triangles.
void attempt(const Patches& patches, const Setting& setting, Tessellation& out)
{
    std::vector<PatchRows> done;
    for (const auto& patch : patches) {
        const std::size_t budget = setting.maxTriangles - std::min(setting.maxTriangles, out.triangleCount());
        Tessellation best;
        PatchRows bestRows;
        bool found = false;
        std::vector<Strategy> strategies{Strategy::kUniform};
        if (setting.method == Method::kMeasured) {
            if (patch->collapsedV0 && patch->link.last.patch >= 0)
                strategies = {Strategy::kAligned};
            else
                strategies.push_back(Strategy::kDerived);
        }
        for (const Strategy strategy : strategies) {
            Tessellation part;
            try {
                PatchRows rows = PatchBuilder(*patch, setting, strategy, budget, part, done).build();
                if (!found || part.triangleCount() < best.triangleCount()) {
                    best = std::move(part);
                    bestRows = std::move(rows);
                    found = true;
                }
            } catch (const OverBudget&) {
            }
        }
        if (!found)
            throw OverBudget{};
        append(out, best);
        done.push_back(std::move(bestRows));
    }
}

/// The measured method's triangle count estimated from a 9 x 9 grid of each
/// patch: drawn area over the area of a triangle between staggered rows.
double estimateTriangles(const Patches& patches, const Setting& s)
{
    constexpr int kGrid = 8;
    double area = 0.0;
    for (const auto& patch : patches) {
        std::vector<Image> grid;
        for (int i = 0; i <= kGrid; ++i)
            for (int j = 0; j <= kGrid; ++j)
                grid.push_back(s.measure.image(patch->point(patch->u0 + (patch->u1 - patch->u0) * j / kGrid,
                                                            patch->v0 + (patch->v1 - patch->v0) * i / kGrid)));
        auto at = [&](int i, int j) -> const Image& { return grid[std::size_t(i * (kGrid + 1) + j)]; };
        auto triangleArea = [](const Image& a, const Image& b, const Image& c) {
            if (!a.has || !b.has || !c.has)
                return 0.0;
            return 0.5 * glm::length(glm::cross(b.mapped - a.mapped, c.mapped - a.mapped));
        };
        for (int i = 0; i < kGrid; ++i)
            for (int j = 0; j < kGrid; ++j)
                area += triangleArea(at(i, j), at(i, j + 1), at(i + 1, j + 1)) +
                        triangleArea(at(i, j), at(i + 1, j + 1), at(i + 1, j));
    }
    return area / (0.5 * s.rowChord() * s.rowSpacing(Strategy::kUniform));
}

} // namespace

Tessellation tessellate(const Patches& patches, const Subdivision& subdivision)
{
    Setting s;
    s.method = subdivision.method;
    s.c1 = subdivision.c1;
    s.c2 = subdivision.c2;
    s.maxTriangles = std::max<std::size_t>(subdivision.maxTriangles, 1);
    if (s.method == Method::kMeasured) {
        s.measure = Measure(&subdivision.map);
        if (!(s.c1 > 0.0))
            s.c1 = std::numeric_limits<double>::infinity();
    } else {
        s.c1 = std::max(1.0, std::floor(s.c1));
        s.c2 = std::max(1.0, std::floor(s.c2));
    }
    bool reduced = false;
    if (s.method == Method::kConstant) {
        // Every patch's grid, linked rows aside: scale both counts down at
        // once rather than through retries.
        double total = 0.0;
        for (const auto& patch : patches)
            total += 2.0 * constantCount(patch->constantU, s) * constantCount(patch->constantV, s);
        if (total > double(s.maxTriangles)) {
            const double f = std::sqrt(double(s.maxTriangles) / total);
            s.c1 = std::max(1.0, std::floor(s.c1 * f));
            s.c2 = std::max(1.0, std::floor(s.c2 * f));
            reduced = true;
        }
    }
    if (s.method == Method::kMeasured && std::isfinite(s.c1)) {
        const double estimate = estimateTriangles(patches, s);
        const double budget = 0.7 * double(s.maxTriangles);
        if (estimate > budget) {
            s.c1 *= std::sqrt(estimate / budget);
            reduced = true;
        }
    }
    for (int tries = 0;; ++tries) {
        Tessellation out;
        try {
            attempt(patches, s, out);
            out.reduced = reduced;
            out.effectiveC1 = s.c1;
            out.effectiveC2 = s.c2;
            out.overruns = tries;
            return out;
        } catch (const OverBudget&) {
            reduced = true;
            const bool coarsest = s.method == Method::kMeasured ? !std::isfinite(s.c1) : s.c1 == 1.0 && s.c2 == 1.0;
            if (coarsest) {
                // A cap below the coarsest tessellation (the fewest segments
                // per turn): that one, whatever it costs.
                s.maxTriangles = std::numeric_limits<std::size_t>::max();
            } else if (s.method == Method::kMeasured) {
                s.c1 = tries < kMaxDoublings ? 2.0 * s.c1 : std::numeric_limits<double>::infinity();
            } else {
                s.c1 = std::max(1.0, std::floor(0.7 * s.c1));
                s.c2 = std::max(1.0, std::floor(0.7 * s.c2));
            }
        }
    }
}

Polyline tessellateCurve(const std::function<Vec3(double)>& curve, double t0, double t1, bool closed,
                         const Subdivision& subdivision, std::size_t maxSegments)
{
    Polyline out;
    const std::size_t minimum = closed ? 3 : 1;
    maxSegments = std::max(maxSegments, minimum);
    if (subdivision.method == Method::kConstant) {
        const double wanted =
            std::max(double(minimum), std::ceil(std::max(1.0, std::floor(subdivision.c1)) * (t1 - t0) - 1e-9));
        std::size_t n = std::size_t(std::min(wanted, 1e18));
        if (n > maxSegments) {
            n = maxSegments;
            out.reduced = true;
        }
        for (std::size_t i = 0; i <= n; ++i)
            out.points.push_back(curve(i == n ? t1 : t0 + (t1 - t0) * double(i) / double(n)));
        out.effective = double(n) / (t1 - t0);
        return out;
    }

    const Measure measure(&subdivision.map);
    auto image = [&](double t) { return measure.image(curve(t)); };
    double c1 = subdivision.c1 > 0.0 ? subdivision.c1 : std::numeric_limits<double>::infinity();
    const double probe = (t1 - t0) / 256;
    const double longestStep = (t1 - t0) / double(minimum);
    {
        // The drawn length over probes (an underestimate): a c1 that would
        // need more than maxSegments is raised at once.
        double length = 0.0;
        Image previous = image(t0);
        for (int i = 1; i <= 256; ++i) {
            const Image next = image(t0 + probe * i);
            length += measure.length(previous, next);
            previous = next;
        }
        if (std::isfinite(c1) && length / c1 > 0.9 * double(maxSegments)) {
            c1 = length / (0.9 * double(maxSegments));
            out.reduced = true;
        }
    }
    for (int tries = 0;; ++tries) {
        std::vector<double> ts{t0};
        Image from = image(t0);
        bool over = false;
        while (ts.back() < t1) {
            const double t = ts.back();
            const double limit = std::min(t1, t + longestStep);
            // Walk probes until one is farther than c1, then bisect the last
            // probe interval for the farthest point within c1.
            double inside = t, outside = -1.0;
            for (double next = std::min(limit, t + probe);; next = std::min(limit, next + probe)) {
                if (measure.length(from, image(next)) > c1) {
                    outside = next;
                    break;
                }
                inside = next;
                if (next >= limit)
                    break;
            }
            double chosen = inside;
            if (outside > 0.0) {
                for (int i = 0; i < 60 && outside - inside > 1e-15; ++i) {
                    const double mid = 0.5 * (inside + outside);
                    const double drawn = measure.length(from, image(mid));
                    if (drawn > c1)
                        outside = mid;
                    else
                        inside = mid;
                    if (drawn <= c1 && drawn >= (1.0 - kCurveTolerance) * c1)
                        break;
                }
                chosen = inside > t ? inside : outside; // a step too steep to resolve
            }
            ts.push_back(chosen >= t1 ? t1 : chosen);
            from = image(ts.back());
            if (ts.size() > maxSegments + 1) {
                over = true;
                break;
            }
        }
        if (!over) {
            for (double t : ts)
                out.points.push_back(curve(t));
            out.effective = c1;
            return out;
        }
        out.reduced = true;
        c1 = std::isfinite(c1) && tries < 60 ? 2.0 * c1 : std::numeric_limits<double>::infinity();
    }
}

} // namespace q3::quadric
