#include "model/water/height_field.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <type_traits>

#include "model/water/leapfrog_kernel.hpp"
#include "model/water/thread_team.hpp"

namespace stoneskip {

const char* to_string(Boundary b) {
  switch (b) {
    case Boundary::periodic: return "periodic";
    case Boundary::reflecting: return "reflecting";
    case Boundary::fixed: return "fixed";
  }
  return "?";
}

namespace {

// Levels a temporal-blocked pass of a periodic field may advance (its image rows on each side).
constexpr int kMostBlockedLevels = 16;
// Two levels larger than this are advanced along a wavefront (HeightField::advance).
constexpr std::size_t kBlockingFromBytes = 1 << 20;

// The value of `all` whose name is s.
template <class E, std::size_t N>
bool parse_named(const std::string& s, const E (&all)[N], E& out) {
  for (E e : all)
    if (s == to_string(e)) {
      out = e;
      return true;
    }
  return false;
}

}  // namespace

bool parse_boundary(const std::string& s, Boundary& out) {
  constexpr Boundary all[] = {Boundary::periodic, Boundary::reflecting, Boundary::fixed};
  return parse_named(s, all, out);
}

const char* to_string(Precision p) { return p == Precision::float64 ? "float64" : "float32"; }

bool parse_precision(const std::string& s, Precision& out) {
  constexpr Precision all[] = {Precision::float64, Precision::float32};
  return parse_named(s, all, out);
}

const char* to_string(StepMode m) { return m == StepMode::full ? "full" : "active_tiles"; }

bool parse_step_mode(const std::string& s, StepMode& out) {
  constexpr StepMode all[] = {StepMode::full, StepMode::active_tiles};
  return parse_named(s, all, out);
}

bool HeightFieldOptions::is_valid(std::string* why) const {
  auto fail = [&](const char* what) {
    if (why) *why = what;
    return false;
  };
  if (nx < 2 || ny < 2) return fail("height field needs nx, ny >= 2");
  if (!(cell_m > 0) || !std::isfinite(cell_m)) return fail("height field: cell_m must be > 0");
  if (!(dt_s > 0) || !std::isfinite(dt_s)) return fail("height field: dt_s must be > 0");
  if (!(wave_speed_m_s >= 0) || !std::isfinite(wave_speed_m_s)) return fail("height field: wave_speed_m_s must be >= 0");
  if (!(damping_per_s >= 0) || !std::isfinite(damping_per_s)) return fail("height field: damping_per_s must be >= 0");
  if (threads < 1 || threads > 256) return fail("height field: threads must be in [1, 256]");
  if (tiles.tile_cells < 1) return fail("height field: tiles.tile_cells must be >= 1");
  if (!(tiles.epsilon_m >= 0) || !std::isfinite(tiles.epsilon_m)) return fail("height field: tiles.epsilon_m must be >= 0");
  return true;
}

std::string ActiveTileSummary::brief() const {
  char buf[200];
  std::snprintf(buf, sizeof buf, "%.3g %% of tile-steps (%ld of %ld), %ld tile + %ld border drops, max dropped %.3g m",
                100 * fraction(), tile_steps, steps * tiles, drops, border_drops, dropped_max_m);
  return buf;
}

HeightField::HeightField(const HeightFieldOptions& options)
    : options_(options), f64_(options.precision == Precision::float64) {
  std::string why;
  if (!options.is_valid(&why)) throw std::invalid_argument(why);
  const std::size_t line = CacheAligned<double>::kAlignment / (f64_ ? sizeof(double) : sizeof(float));
  origin_ = line - 1;
  stride_ = (origin_ + static_cast<std::size_t>(options.nx) + 2 + line - 1) / line * line;
  // A periodic field keeps the images of up to kMostBlockedLevels rows on each side, which the
  // temporal-blocked advance recomputes (one fewer per level) instead of wrapping each level.
  ghost_rows_ = options.boundary == Boundary::periodic ? std::min(kMostBlockedLevels, options.ny) : 1;
  // One vector of slack at the end: the aligned kernel reads the vector after a row's last cell.
  const std::size_t n = levels_size_ = stride_ * (static_cast<std::size_t>(options.ny) + 2 * ghost_rows_) + line;
  // The two levels half a page apart (CacheAligned): no 4K aliasing between them.
  if (f64_) {
    cur64_ = decltype(cur64_)(n, 0.0, CacheAligned<double>(0));
    prev64_ = decltype(prev64_)(n, 0.0, CacheAligned<double>(CacheAligned<double>::kPage / 2));
  } else {
    cur32_ = decltype(cur32_)(n, 0.0f, CacheAligned<float>(0));
    prev32_ = decltype(prev32_)(n, 0.0f, CacheAligned<float>(CacheAligned<float>::kPage / 2));
  }
  if (options.threads > 1) team_ = std::make_unique<ThreadTeam>(options.threads);
  const int tc = options.tiles.tile_cells;
  tiles_x_ = (options.nx + tc - 1) / tc;
  tiles_y_ = (options.ny + tc - 1) / tc;
  const std::size_t nt = static_cast<std::size_t>(tiles_x_) * tiles_y_;
  holds_.assign(nt, 0);
  nonzero_.assign(nt, 0);
  step_flag_.assign(nt, 0);
  activity64_.assign(nt, 0.0);
  activity32_.assign(nt, 0.0f);
  active_.reserve(nt);
  runs_.reserve(nt);
  tile_neighbours_.resize(nt);
  const bool periodic = options.boundary == Boundary::periodic;
  for (int ty = 0; ty < tiles_y_; ++ty)
    for (int tx = 0; tx < tiles_x_; ++tx)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          int qx = tx + dx, qy = ty + dy;
          if (periodic) {
            qx = (qx + tiles_x_) % tiles_x_;
            qy = (qy + tiles_y_) % tiles_y_;
          }
          const bool inside = qx >= 0 && qx < tiles_x_ && qy >= 0 && qy < tiles_y_;
          tile_neighbours_[static_cast<std::size_t>(ty) * tiles_x_ + tx][3 * (dy + 1) + dx + 1] = inside ? qy * tiles_x_ + qx : -1;
        }
  tiles_summary_.tiles = options.mode == StepMode::active_tiles ? static_cast<long>(nt) : 0;
}

HeightField::~HeightField() = default;
HeightField::HeightField(HeightField&&) noexcept = default;
HeightField& HeightField::operator=(HeightField&&) noexcept = default;

namespace {

// Fills the ghost layer of a padded (nx+2)×(ny+2) array from its interior (model/README.md §2.1 boundaries);
// p points at the ghost corner (−1, −1), rows w apart.
template <class Real>
void fill_ghosts(Real* p, int nx, int ny, std::size_t w, Boundary boundary) {
  switch (boundary) {
    case Boundary::fixed:
      return;  // ghosts are zero from construction and never written
    case Boundary::periodic:
      for (int j = 1; j <= ny; ++j) {
        p[j * w + 0] = p[j * w + nx];
        p[j * w + nx + 1] = p[j * w + 1];
      }
      for (std::size_t i = 0; i < static_cast<std::size_t>(nx) + 2; ++i) {  // whole rows, so the corners wrap too
        p[i] = p[ny * w + i];
        p[(ny + 1) * w + i] = p[w + i];
      }
      return;
    case Boundary::reflecting:
      for (int j = 1; j <= ny; ++j) {
        p[j * w + 0] = p[j * w + 1];
        p[j * w + nx + 1] = p[j * w + nx];
      }
      for (std::size_t i = 0; i < static_cast<std::size_t>(nx) + 2; ++i) {
        p[i] = p[w + i];
        p[(ny + 1) * w + i] = p[ny * w + i];
      }
      return;
  }
}

inline int wrap(int i, int n) {
  i %= n;
  return i < 0 ? i + n : i;
}

}  // namespace

void HeightField::build_forcing(const DraughtPatch& p) {
  // C = d² L[b] (model/README.md §2.4) on the box around the patch, b extended beyond the grid as the
  // boundary extends z: periodic images (accumulated when the box is wrapped onto the grid),
  // mirrored ghosts (reflecting: a point on the edge also feeds the cell it mirrors into) or zero
  // (fixed). Scatter form: b at grid point g feeds the target t = g' − δ for every offset δ of the
  // 3×3 stencil and every image g' of g, with weight w_δ (the stencil is symmetric, w_δ = w_−δ).
  const int nx = options_.nx, ny = options_.ny;
  const bool periodic = options_.boundary == Boundary::periodic;
  const bool mirror = options_.boundary == Boundary::reflecting;
  const Stencil& st = options_.stencil;
  fi0_ = p.i0 - 1;
  fj0_ = p.j0 - 1;
  fni_ = p.ni + 2;
  fnj_ = p.nj + 2;
  forcing_.assign(static_cast<std::size_t>(fni_) * fnj_, 0.0);
  auto weight = [&](int dx, int dy) { return dx == 0 && dy == 0 ? st.centre : (dx == 0 || dy == 0 ? st.orth : st.diag); };
  for (int c = 0; c < p.nj; ++c)
    for (int a = 0; a < p.ni; ++a) {
      const double v = p.at(a, c);
      if (v == 0) continue;
      const int i = p.i0 + a, j = p.j0 + c;
      if (periodic) {
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx)
            forcing_[static_cast<std::size_t>(c + 1 - dy) * fni_ + (a + 1 - dx)] += weight(dx, dy) * v;
        continue;
      }
      if (i < 0 || i >= nx || j < 0 || j >= ny) continue;  // beyond the rim: not on the water
      int xi[3] = {i, 0, 0}, yj[3] = {j, 0, 0};
      int nxi = 1, nyj = 1;
      if (mirror) {
        if (i == 0) xi[nxi++] = -1;
        if (i == nx - 1) xi[nxi++] = nx;
        if (j == 0) yj[nyj++] = -1;
        if (j == ny - 1) yj[nyj++] = ny;
      }
      for (int q = 0; q < nyj; ++q)
        for (int r = 0; r < nxi; ++r)
          for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
              const int ti = xi[r] - dx, tj = yj[q] - dy;
              if (ti < 0 || ti >= nx || tj < 0 || tj >= ny) continue;
              forcing_[static_cast<std::size_t>(tj - fj0_) * fni_ + (ti - fi0_)] += weight(dx, dy) * v;
            }
    }
}

template <class Real>
void HeightField::step_impl(std::vector<Real, CacheAligned<Real>>& curv, std::vector<Real, CacheAligned<Real>>& prevv,
                            const DraughtPatch* draught) {
  // Lee & Baek 2013 Eq. 11 in the centred-damping form of model/README.md §2.1, forced as in model/README.md §2.4.
  const double mdt = options_.damping_per_s * options_.dt_s;
  const double inv = 1.0 / (2 + mdt);
  const double s = 2 * options_.courant() * options_.courant() * inv;  // 2c²Δt²/d² /(2+μΔt)
  const Stencil& st = options_.stencil;
  const LeapfrogWeights<Real> wts = leapfrog_weights<Real>(st.centre, st.orth, st.diag, options_.courant(), mdt);
  const bool diagonal = wts.diag != 0;
  const int nx = options_.nx, ny = options_.ny;
  const std::ptrdiff_t w = static_cast<std::ptrdiff_t>(stride_);
  const bool periodic = options_.boundary == Boundary::periodic;
  const bool forced = draught && !draught->empty() && s != 0;
  if (forced) build_forcing(*draught);
  Real* z = curv.data();
  Real* zp = prevv.data();  // holds z⁻, receives z⁺
  // Work is cut into a few chunks per thread, claimed by whichever thread is free (thread_team.hpp).
  const int chunks_per_thread = 4;
  const int parts = team_ ? chunks_per_thread * team_->size() : 1;

  if (options_.mode == StepMode::full) {
    fill_ghosts(z + ghost_corner(), nx, ny, stride_, options_.boundary);
    auto rows = [&](int part) {
      const PartRange r = part_range(ny, part, parts);
      const std::ptrdiff_t k = static_cast<std::ptrdiff_t>(index(0, static_cast<int>(r.begin)));
      leapfrog_block(zp + k, z + k, nx, r.end - r.begin, w, wts, diagonal);
    };
    if (team_)
      team_->run(rows, std::min(parts, ny));
    else
      rows(0);
  } else {
    // Spec §2.6. A tile "holds" while max(|z|, |z − z⁻|) > ε over its cells; it is active while it
    // or a neighbour holds (or the draught's box touches it). 1: drop (set to zero, keeping what
    // they held) the nonzero tiles that are not active. 2: step the active tiles. 3: a quiet tile
    // next to a nonzero active one would receive something across its border; that update is
    // evaluated on its border cells only and dropped too (recorded, not written). The run then
    // differs from the full field only by the free evolution of what was dropped; with ε = 0 every
    // nonzero tile holds, so nothing nonzero is ever dropped and the result is the full field's.
    const int tc = options_.tiles.tile_cells;
    const double eps = options_.tiles.epsilon_m;
    // Neighbour q of tile t (q = 3(dy + 1) + dx + 1, 4 = itself), −1 beyond a non-periodic edge.
    auto any_neighbour = [&](int t, const std::vector<unsigned char>& flag) {
      for (int q : tile_neighbours_[t])
        if (q >= 0 && flag[q]) return true;
      return false;
    };
    const int nt = tiles_x_ * tiles_y_;
    for (int t = 0; t < nt; ++t) step_flag_[t] = any_neighbour(t, holds_);
    if (forced) {
      // Tiles of the forcing box's grid points (wrapped, or clipped to the grid).
      if (periodic) {
        for (int j = fj0_; j < fj0_ + fnj_; ++j)
          for (int i = fi0_; i < fi0_ + fni_; ++i) step_flag_[tile_of(wrap(i, nx), wrap(j, ny))] = 1;
      } else {
        const int ilo = std::max(fi0_, 0), ihi = std::min(fi0_ + fni_ - 1, nx - 1);
        const int jlo = std::max(fj0_, 0), jhi = std::min(fj0_ + fnj_ - 1, ny - 1);
        for (int j = jlo; j <= jhi; ++j)
          for (int i = ilo; i <= ihi; ++i) step_flag_[tile_of(i, j)] = 1;
      }
    }
    double dropped_sq = 0, dropped_max = 0;
    // Sets cells of a (and b) to zero, keeping the sum of squares and the largest magnitude.
    auto drop_cells = [&](int i_begin, int i_end, int j_begin, int j_end, Real* a, Real* b) {
      bool held = false;
      for (int j = j_begin; j < j_end; ++j)
        for (int i = i_begin; i < i_end; ++i) {
          const std::size_t k = index(i, j);
          const double u = a[k], v = b ? static_cast<double>(b[k]) : 0.0;
          if (u == 0 && v == 0) continue;
          held = true;
          dropped_sq += u * u + v * v;
          dropped_max = std::max(dropped_max, std::max(std::abs(u), std::abs(v)));
          a[k] = 0;
          if (b) b[k] = 0;
        }
      return held;
    };
    for (int t = 0; t < nt; ++t) {
      if (!nonzero_[t] || step_flag_[t]) continue;
      const int i0 = (t % tiles_x_) * tc, j0 = (t / tiles_x_) * tc;
      if (drop_cells(i0, std::min(i0 + tc, nx), j0, std::min(j0 + tc, ny), z, zp)) ++tiles_summary_.drops;
      nonzero_[t] = 0;
    }
    active_.clear();
    for (int t = 0; t < nt; ++t)
      if (step_flag_[t]) active_.push_back(t);
    // 2: step them band by band (a band = a row of tiles), row by row across each run of adjacent
    // active tiles, so that memory is streamed as in the full step; the kernel measures each
    // tile's activity max(|z⁺|, |z⁺ − z|) on the way.
    fill_ghosts(z + ghost_corner(), nx, ny, stride_, options_.boundary);
    const long count = static_cast<long>(active_.size());
    Real* activity = nullptr;
    if constexpr (std::is_same_v<Real, double>)
      activity = activity64_.data();
    else
      activity = activity32_.data();
    for (int t : active_) activity[t] = 0;
    // Runs of adjacent active tiles, band by band.
    runs_.clear();
    for (int ty = 0; ty < tiles_y_; ++ty)
      for (int tx = 0; tx < tiles_x_;) {
        if (!step_flag_[ty * tiles_x_ + tx]) {
          ++tx;
          continue;
        }
        const int first = tx;
        while (tx < tiles_x_ && step_flag_[ty * tiles_x_ + tx]) ++tx;
        runs_.push_back({ty, first, tx});
      }
    auto bands = [&](int part) {
      const PartRange r = part_range(static_cast<long>(runs_.size()), part, parts);
      for (long q = r.begin; q < r.end; ++q) {
        const TileRun& run = runs_[q];
        const int i0 = run.first * tc, cells = std::min(run.end * tc, nx) - i0;
        Real* act = activity + run.band * tiles_x_ + run.first;
        for (int j = run.band * tc; j < std::min((run.band + 1) * tc, ny); ++j) {
          const std::size_t k = index(i0, j);
          leapfrog_row_chunks(zp + k, z + k, cells, w, wts, diagonal, tc, act);
        }
      }
    };
    if (team_)
      team_->run(bands, parts);
    else
      bands(0);
    // 3: a quiet tile next to a nonzero active tile q would receive across their common side
    // L_i = s(orth e_i + diag (e_{i−1} + e_{i+1})), e the line of q's cells along the side (one
    // cell at a corner, diag e). Not computed: dropped, and recorded by its bound ‖L‖₂ ≤
    // (|s orth| + 2|s diag|) ‖e‖₂ (corner |s diag| |e|), so the summary's dropped norm bounds,
    // rather than equals, what the borders lost; O(side) per quiet tile, no update evaluated.
    const double leak_side = std::abs(s * st.orth) + 2 * std::abs(s * st.diag), leak_corner = std::abs(s * st.diag);
    auto cell = [&](int i, int j) -> double {
      if (periodic) {
        i = wrap(i, nx);
        j = wrap(j, ny);
      }
      return std::abs(static_cast<double>(z[index(i, j)]));
    };
    for (int t = 0; t < nt; ++t) {
      if (step_flag_[t] || !any_neighbour(t, nonzero_)) continue;
      const int i0 = (t % tiles_x_) * tc, j0 = (t / tiles_x_) * tc;
      const int i1 = std::min(i0 + tc, nx), j1 = std::min(j0 + tc, ny);
      double norm = 0;
      for (int q = 0; q < 9; ++q) {
        const int nb = tile_neighbours_[t][q];
        if (q == 4 || nb < 0 || !nonzero_[nb]) continue;
        const int dx = q % 3 - 1, dy = q / 3 - 1;
        const int ei = dx < 0 ? i0 - 1 : i1, ej = dy < 0 ? j0 - 1 : j1;  // q's line next to the tile
        double sq = 0, mx = 0;
        if (dx != 0 && dy != 0) {
          mx = cell(ei, ej);
          sq = mx * mx;
        } else if (dy != 0) {
          for (int i = i0; i < i1; ++i) {
            const double e = cell(i, ej);
            sq += e * e;
            mx = std::max(mx, e);
          }
        } else {
          for (int j = j0; j < j1; ++j) {
            const double e = cell(ei, j);
            sq += e * e;
            mx = std::max(mx, e);
          }
        }
        const double coef = dx != 0 && dy != 0 ? leak_corner : leak_side;
        norm += coef * std::sqrt(sq);
        dropped_max = std::max(dropped_max, coef * mx);
      }
      if (norm > 0) ++tiles_summary_.border_drops;
      dropped_sq += norm * norm;
    }
    tiles_summary_.dropped_max_m = std::max(tiles_summary_.dropped_max_m, dropped_max);
    tiles_summary_.dropped_norm_sum_m += std::sqrt(dropped_sq);
    std::fill(holds_.begin(), holds_.end(), 0);
    std::fill(nonzero_.begin(), nonzero_.end(), 0);
    for (int t : active_) {
      holds_[t] = !(activity[t] <= eps);  // a NaN holds
      nonzero_[t] = !(activity[t] <= 0);
    }
    tiles_summary_.tile_steps += count;
  }

  if (forced) {
    // z⁺ += 2c²Δt²/(2 + μΔt) · L[b] = s · C on the box (wrapped onto a periodic grid).
    for (int c = 0; c < fnj_; ++c)
      for (int a = 0; a < fni_; ++a) {
        const double f = forcing_[static_cast<std::size_t>(c) * fni_ + a];
        if (f == 0) continue;
        int i = fi0_ + a, j = fj0_ + c;
        if (periodic) {
          i = wrap(i, nx);
          j = wrap(j, ny);
        } else if (i < 0 || i >= nx || j < 0 || j >= ny) {
          continue;
        }
        const std::size_t k = index(i, j);
        zp[k] = static_cast<Real>(static_cast<double>(zp[k]) + s * f);
        if (options_.mode == StepMode::active_tiles) holds_[tile_of(i, j)] = nonzero_[tile_of(i, j)] = 1;
      }
  }
  curv.swap(prevv);
  ++steps_;
  ++tiles_summary_.steps;
  time_s_ = steps_ * options_.dt_s;
}

void HeightField::step() {
  if (f64_)
    step_impl(cur64_, prev64_, nullptr);
  else
    step_impl(cur32_, prev32_, nullptr);
}

void HeightField::step(const DraughtPatch& draught) {
  if (f64_)
    step_impl(cur64_, prev64_, &draught);
  else
    step_impl(cur32_, prev32_, &draught);
}

namespace {

// The boundary of model/README.md §2.1 applied row by row inside the wavefront (leapfrog_wavefront's
// hooks), with the values fill_ghosts gives a whole level: a periodic field recomputes its images
// (halo rows) and wraps each row's two ghost cells; a reflecting one mirrors each row's edge cells
// and copies its first and last rows, ghosts included, to the ghost rows; a fixed one holds zeros.
template <class Real>
struct RowBoundary {
  int nx = 0, ny = 0;
  std::ptrdiff_t w = 0;
  Boundary boundary = Boundary::fixed;

  static void before_pass(void* self, Real* level, Real* previous, int levels) {
    const RowBoundary& b = *static_cast<RowBoundary*>(self);
    if (b.boundary != Boundary::periodic) {
      fill_ghosts(level - b.w - 1, b.nx, b.ny, static_cast<std::size_t>(b.w), b.boundary);
      return;
    }
    // The level's rows with their ghost cells, then `levels` image rows above and below of both levels.
    for (int j = 0; j < b.ny; ++j) after_row(self, level, j);
    const std::size_t row = static_cast<std::size_t>(b.w) * sizeof(Real);
    for (Real* p : {level, previous})
      for (int r = 1; r <= levels; ++r) {
        std::memcpy(p - r * b.w - 1, p + (b.ny - r) * b.w - 1, row);
        std::memcpy(p + (b.ny - 1 + r) * b.w - 1, p + (r - 1) * b.w - 1, row);
      }
  }
  static void after_row(void* self, Real* level, std::ptrdiff_t j) {
    const RowBoundary& b = *static_cast<RowBoundary*>(self);
    Real* r = level + j * b.w;
    if (b.boundary == Boundary::periodic) {
      r[-1] = r[b.nx - 1];
      r[b.nx] = r[0];
      return;
    }
    r[-1] = r[0];
    r[b.nx] = r[b.nx - 1];
    const std::size_t row = static_cast<std::size_t>(b.nx + 2) * sizeof(Real);
    if (j == 0) std::memcpy(r - b.w - 1, r - 1, row);
    if (j == b.ny - 1) std::memcpy(r + b.w - 1, r - 1, row);
  }
};

}  // namespace

template <class Real>
void HeightField::advance_blocked(std::vector<Real, CacheAligned<Real>>& curv, std::vector<Real, CacheAligned<Real>>& prevv,
                                  long n) {
  const double mdt = options_.damping_per_s * options_.dt_s;
  const Stencil& st = options_.stencil;
  const LeapfrogWeights<Real> wts = leapfrog_weights<Real>(st.centre, st.orth, st.diag, options_.courant(), mdt);
  RowBoundary<Real> rb{options_.nx, options_.ny, static_cast<std::ptrdiff_t>(stride_), options_.boundary};
  WavefrontHooks<Real> hooks;
  hooks.context = &rb;
  hooks.before_pass = &RowBoundary<Real>::before_pass;
  if (options_.boundary != Boundary::fixed) hooks.after_row = &RowBoundary<Real>::after_row;
  if (options_.boundary == Boundary::periodic) hooks.halo_rows = ghost_rows_;
  const std::size_t k = index(0, 0);
  for (long done = 0; done < n;) {
    const int steps = static_cast<int>(std::min<long>(n - done, 1 << 30));
    leapfrog_wavefront(curv.data() + k, prevv.data() + k, options_.nx, options_.ny, static_cast<std::ptrdiff_t>(stride_), wts,
                       wts.diag != 0, steps, hooks);
    if (steps % 2) curv.swap(prevv);
    done += steps;
  }
  steps_ += n;
  tiles_summary_.steps += n;
  time_s_ = steps_ * options_.dt_s;
}

bool HeightField::advance_is_blocked() const {
  // Blocking pays once the two levels no longer fit L2 (1 MB on the machines measured); below,
  // whole sweeps are as fast and have no per-row work.
  const std::size_t level_bytes = levels_size_ * (f64_ ? sizeof(double) : sizeof(float));
  return options_.mode == StepMode::full && !team_ && 2 * level_bytes > kBlockingFromBytes;
}

void HeightField::advance(long n) {
  if (n >= 2 && advance_is_blocked()) {
    if (f64_)
      advance_blocked(cur64_, prev64_, n);
    else
      advance_blocked(cur32_, prev32_, n);
    return;
  }
  for (long i = 0; i < n; ++i) step();
}

void HeightField::restart() {
  // After the state was set from outside: measure every tile's activity max(|z|, |z − z⁻|).
  const int nx = options_.nx, ny = options_.ny;
  std::fill(activity64_.begin(), activity64_.end(), 0.0);
  std::fill(activity32_.begin(), activity32_.end(), 0.0f);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) note_activity(i, j);
  time_s_ = 0;
  steps_ = 0;
  tiles_summary_ = ActiveTileSummary{};
  tiles_summary_.tiles = options_.mode == StepMode::active_tiles ? static_cast<long>(holds_.size()) : 0;
}

void HeightField::note_activity(int i, int j) {
  const int t = tile_of(i, j);
  const double z = height(i, j), a = std::max(std::abs(z), std::abs(z - previous_height(i, j)));
  double& act64 = activity64_[t];
  float& act32 = activity32_[t];
  const double before = f64_ ? act64 : static_cast<double>(act32);
  const double now = !(a <= before) ? a : before;  // a NaN stays
  act64 = now;
  act32 = static_cast<float>(now);
  holds_[t] = !(now <= options_.tiles.epsilon_m);
  nonzero_[t] = !(now <= 0);
}

void HeightField::set_height(int i, int j, double z) {
  const std::size_t k = index(i, j);
  if (f64_)
    cur64_[k] = z;
  else
    cur32_[k] = static_cast<float>(z);
  note_activity(i, j);
}

void HeightField::set_state(const std::vector<double>& z0, const std::vector<double>& v0) {
  const int nx = options_.nx, ny = options_.ny;
  const std::size_t n = static_cast<std::size_t>(nx) * ny;
  if (z0.size() != n || (!v0.empty() && v0.size() != n)) throw std::invalid_argument("set_state: wrong field size");
  // The start is computed in double whatever the storage, then stored.
  std::vector<double> cur(levels_size_, 0.0);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) cur[index(i, j)] = z0[static_cast<std::size_t>(j) * nx + i];
  fill_ghosts(cur.data() + ghost_corner(), nx, ny, stride_, options_.boundary);
  const std::ptrdiff_t w = static_cast<std::ptrdiff_t>(stride_);
  const double id2 = 1.0 / (options_.cell_m * options_.cell_m);
  const Stencil& st = options_.stencil;
  const double dt = options_.dt_s, c2 = options_.wave_speed_m_s * options_.wave_speed_m_s, mu = options_.damping_per_s;
  std::vector<double> prev(cur.size(), 0.0);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const std::ptrdiff_t k = static_cast<std::ptrdiff_t>(index(i, j));
      const double lap = id2 * (st.centre * cur[k] + st.orth * (cur[k - 1] + cur[k + 1] + cur[k - w] + cur[k + w]) +
                                st.diag * (cur[k - w - 1] + cur[k - w + 1] + cur[k + w - 1] + cur[k + w + 1]));
      const double v = v0.empty() ? 0.0 : v0[static_cast<std::size_t>(j) * nx + i];
      prev[k] = cur[k] - dt * v + 0.5 * dt * dt * (c2 * lap - mu * v);
    }
  if (f64_) {
    cur64_.assign(cur.begin(), cur.end());
    prev64_.assign(prev.begin(), prev.end());
  } else {
    for (std::size_t k = 0; k < cur.size(); ++k) {
      cur32_[k] = static_cast<float>(cur[k]);
      prev32_[k] = static_cast<float>(prev[k]);
    }
  }
  restart();
}

void HeightField::set_levels(const std::vector<double>& z, const std::vector<double>& z_previous) {
  const int nx = options_.nx, ny = options_.ny;
  const std::size_t n = static_cast<std::size_t>(nx) * ny;
  if (z.size() != n || z_previous.size() != n) throw std::invalid_argument("set_levels: wrong field size");
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const std::size_t k = index(i, j), q = static_cast<std::size_t>(j) * nx + i;
      if (f64_) {
        cur64_[k] = z[q];
        prev64_[k] = z_previous[q];
      } else {
        cur32_[k] = static_cast<float>(z[q]);
        prev32_[k] = static_cast<float>(z_previous[q]);
      }
    }
  restart();
}

void HeightField::heights(std::vector<double>& out) const {
  const int nx = options_.nx, ny = options_.ny;
  out.resize(static_cast<std::size_t>(nx) * ny);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) out[static_cast<std::size_t>(j) * nx + i] = height(i, j);
}

double HeightField::volume_m3() const {
  double s = 0;
  for (int j = 0; j < options_.ny; ++j)
    for (int i = 0; i < options_.nx; ++i) s += height(i, j);
  return s * options_.cell_m * options_.cell_m;
}

HeightField::Bilinear HeightField::bilinear(double x_m, double y_m) const {
  const int nx = options_.nx, ny = options_.ny;
  double gx = x_m / options_.cell_m, gy = y_m / options_.cell_m;
  const bool wrap_xy = options_.boundary == Boundary::periodic;
  if (wrap_xy) {
    gx -= nx * std::floor(gx / nx);
    gy -= ny * std::floor(gy / ny);
  } else {
    gx = std::clamp(gx, 0.0, nx - 1.0);
    gy = std::clamp(gy, 0.0, ny - 1.0);
  }
  int i0 = std::min(static_cast<int>(std::floor(gx)), nx - 1), j0 = std::min(static_cast<int>(std::floor(gy)), ny - 1);
  double fx = gx - i0, fy = gy - j0;
  int i1 = i0 + 1, j1 = j0 + 1;
  if (wrap_xy) {
    i1 %= nx;
    j1 %= ny;
  } else {
    i1 = std::min(i1, nx - 1);
    j1 = std::min(j1, ny - 1);
  }
  return {i0, i1, j0, j1, (1 - fx) * (1 - fy), fx * (1 - fy), (1 - fx) * fy, fx * fy};
}

double HeightField::interpolate(double x_m, double y_m) const {
  const Bilinear b = bilinear(x_m, y_m);
  return b.w00 * height(b.i0, b.j0) + b.w10 * height(b.i1, b.j0) + b.w01 * height(b.i0, b.j1) + b.w11 * height(b.i1, b.j1);
}

std::pair<double, double> HeightField::interpolate_both_levels(double x_m, double y_m) const {
  const Bilinear b = bilinear(x_m, y_m);
  auto at = [&](auto level) {
    return b.w00 * level(b.i0, b.j0) + b.w10 * level(b.i1, b.j0) + b.w01 * level(b.i0, b.j1) + b.w11 * level(b.i1, b.j1);
  };
  return {at([this](int i, int j) { return height(i, j); }), at([this](int i, int j) { return previous_height(i, j); })};
}

}  // namespace stoneskip
