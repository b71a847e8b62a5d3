#pragma once
// The water surface as a height field (model/README.md §2.1, Lee & Baek 2013 Eq. 8–11):
//   z_tt = c² ∇²(z + b) − μ z_t  on nx × ny cells of size d,
// stepped with the leapfrog of Lengyel's height field with centred damping
//   z⁺ = (4 z − (2 − μΔt) z⁻ + 2 c²Δt² L[z + b]) / (2 + μΔt),
// L any 3×3 stencil (model/water/stencil.hpp), b the stone's draught (model/README.md §2.4; zero for free
// water, model/water/draught_patch.hpp). Storage: two padded (nx+2)×(ny+2) arrays with a ghost
// layer that the boundary condition fills before each step, so the interior update has no
// branches and a step allocates nothing. z⁺ overwrites z⁻ in place (each cell reads only its own
// z⁻), then the two buffers swap.
//
// Speed (model/water/leapfrog_kernel.hpp): a SIMD row kernel chosen at run time for the CPU,
// optionally split over a team of threads kept alive between steps (they pay only where a core is
// free: on a shared 2-core machine they did not), in float64 or float32 storage (float32 steps
// in an increment form that keeps a uniform level exact; verification/waves/precision_error.hpp
// measures its error).
// Active tiles (model/README.md §2.6): StepMode::active_tiles steps only the tiles of tile_cells² cells that
// hold |z| or |z − z⁻| above ε or have a neighbour that does (or lie under the draught). With
// ε = 0 the result is bit-identical to StepMode::full (the update of a cell whose own and
// neighbours' z and z⁻ are zero is zero). With ε > 0 the nonzero tiles that are not active are
// set to zero, and what a quiet tile would receive across its border from an active neighbour is
// not computed; both are "dropped", and the summary keeps their 2-norm (the border part by a bound
// from the neighbour's facing line of cells). The scheme is linear, so the difference from the
// full field is the free evolution of what was dropped (plus rounding): model/water/
// propagator_bound.hpp bounds it, verification/waves/active_tiles_study.hpp measures it.
#include <array>
#include <cstddef>
#include <memory>
#include <new>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "model/water/draught_patch.hpp"
#include "model/water/stencil.hpp"

namespace stoneskip {

class ThreadTeam;

// Storage aligned to 64 bytes (a cache line, an AVX-512 vector), so that with the padding below
// every row's first interior cell starts a cache line. An allocator made with a page offset
// starts its storage that many bytes into a 4 KB page: the two levels of a field start half a
// page apart, so that the loads of one level and the stores into the other in the same step do
// not share their address bits below 4 KB (loads that do are held behind the stores: 4K
// aliasing; measured 5 % at 500², whose rows are 4 KB). The offset travels with the storage
// (a swap of two levels swaps their allocators).
template <class T>
struct CacheAligned {
  using value_type = T;
  static constexpr std::size_t kAlignment = 64, kPage = 4096;
  using propagate_on_container_copy_assignment = std::true_type;
  using propagate_on_container_move_assignment = std::true_type;
  using propagate_on_container_swap = std::true_type;
  bool paged = false;           // storage placed within a page (else only aligned)
  std::size_t page_offset = 0;  // where in the page, bytes: a multiple of kAlignment below kPage
  CacheAligned() = default;
  explicit CacheAligned(std::size_t offset_bytes) : paged(true), page_offset(offset_bytes % kPage / kAlignment * kAlignment) {}
  template <class U>
  CacheAligned(const CacheAligned<U>& o) : paged(o.paged), page_offset(o.page_offset) {}
  T* allocate(std::size_t n) {
    return reinterpret_cast<T*>(static_cast<char*>(::operator new(bytes(n), alignment())) + page_offset);
  }
  // The unsized aligned delete: the sized one is not declared where sized deallocation is off
  // (clang before 19 by default: the fuzz build, tools/README.md, failed to compile).
  void deallocate(T* p, std::size_t) { ::operator delete(reinterpret_cast<char*>(p) - page_offset, alignment()); }
  friend bool operator==(const CacheAligned& a, const CacheAligned& b) { return a.paged == b.paged && a.page_offset == b.page_offset; }

 private:
  std::size_t bytes(std::size_t n) const { return n * sizeof(T) + page_offset; }
  std::align_val_t alignment() const { return std::align_val_t(paged ? kPage : kAlignment); }
};

enum class Boundary {
  periodic,    // the grid tiles the plane (verification against the spectral reference)
  reflecting,  // zero normal slope: ghost cells mirror the edge cells (a wall)
  fixed,       // z = 0 in the ghost cells, half a cell outside the edge (a clamped rim)
};
const char* to_string(Boundary b);
bool parse_boundary(const std::string& s, Boundary& out);

// Storage of the heights. Verification runs in float64; float32 halves the memory traffic of a
// step (its error against float64 is measured by verification/waves/stencil_throughput.hpp).
enum class Precision { float64, float32 };
const char* to_string(Precision p);
bool parse_precision(const std::string& s, Precision& out);

enum class StepMode { full, active_tiles };
const char* to_string(StepMode m);
bool parse_step_mode(const std::string& s, StepMode& out);

struct ActiveTileOptions {
  int tile_cells = 32;     // a tile is tile_cells × tile_cells cells (the last row/column may be smaller)
  double epsilon_m = 0;    // activity threshold ε on |z| and |z − z⁻|; 0 = exact
};

struct HeightFieldOptions {
  int nx = 64, ny = 64;
  double cell_m = 1.0 / 64;
  double wave_speed_m_s = 1;  // c
  double damping_per_s = 0;   // μ
  double dt_s = 0.5 / 64;
  Stencil stencil;
  Boundary boundary = Boundary::periodic;
  Precision precision = Precision::float64;
  int threads = 1;            // threads that share a step (a team kept alive with the field)
  StepMode mode = StepMode::full;
  ActiveTileOptions tiles;    // used when mode == active_tiles

  double courant() const { return wave_speed_m_s * dt_s / cell_m; }  // σ = cΔt/d
  // False with the reason in *why (the first problem found, naming the option).
  bool is_valid(std::string* why = nullptr) const;
};

// What active-tile stepping did over a field's life (model/README.md §2.6). In StepMode::full every tile is
// stepped at every step and nothing is dropped.
struct ActiveTileSummary {
  long steps = 0;
  long tiles = 0;                 // tiles in the field
  long tile_steps = 0;            // tiles stepped, summed over steps
  long drops = 0;                 // nonzero tiles set to zero: neither they nor a neighbour held > ε
  long border_drops = 0;          // quiet tiles whose nonzero border update (from an active neighbour) was dropped
  double dropped_max_m = 0;       // largest |value| dropped
  double dropped_norm_sum_m = 0;  // Σ over steps of the 2-norm (over cells, both levels) of what that step dropped
  // Both counts stay 0 for ε = 0. The error bound: ‖(z − z_full)_n, (z − z_full)_{n−1}‖₂ ≤ K_n ·
  // dropped_norm_sum_m, K_n the largest norm of the free leapfrog's n-step propagator over modes.
  double fraction() const { return steps > 0 && tiles > 0 ? static_cast<double>(tile_steps) / (static_cast<double>(steps) * tiles) : 1.0; }
  std::string brief() const;      // "12.5 % of tile-steps (3200 of 25600), 14 + 3 drops, max dropped 1e-07 m"
};

class HeightField {
 public:
  explicit HeightField(const HeightFieldOptions& options);  // throws std::invalid_argument (is_valid)
  ~HeightField();
  HeightField(const HeightField&) = delete;
  HeightField& operator=(const HeightField&) = delete;
  HeightField(HeightField&&) noexcept;
  HeightField& operator=(HeightField&&) noexcept;

  // Sets z(0) = z0 and z_t(0) = v0 (row-major, x fastest, size nx·ny) and the leapfrog's
  // previous level by Taylor expansion with the scheme's own acceleration:
  // z(−Δt) = z0 − Δt v0 + (Δt²/2)(c² L[z0] − μ v0), a local error O(Δt³) that keeps the
  // global error O(Δt²). An empty v0 means zero velocity. (Without draught: a forced run starts
  // with b(0) = 0, or accepts the O(Δt²) start error of a b(0) that is not.)
  void set_state(const std::vector<double>& z0, const std::vector<double>& v0 = {});

  // Sets both time levels directly: z(t) = z and z(t − Δt) = z_previous (a restart, or a test).
  void set_levels(const std::vector<double>& z, const std::vector<double>& z_previous);

  void step();                              // one free step (b = 0); no allocation
  // One forced step with the draught b at the start of the step (model/README.md §2.4): the free update plus
  // 2c²Δt² L[b] / (2 + μΔt) on the box around b, O(box); an empty patch costs nothing. No
  // allocation once the scratch has grown to the largest patch seen.
  void step(const DraughtPatch& draught);
  // n free steps, bit for bit what n calls of step() give. Where nothing looks in between (free
  // water, the ring phase of a scene, a study's run), StepMode::full on one thread takes them
  // along a wavefront (model/water/leapfrog_kernel.hpp, temporal blocking) once the two levels
  // outgrow L2, the boundary applied to each row of each level as it is computed.
  void advance(long n);
  // Whether advance(n ≥ 2) takes the wavefront on this field (full mode, one thread, levels over L2).
  bool advance_is_blocked() const;

  const HeightFieldOptions& options() const { return options_; }
  int nx() const { return options_.nx; }
  int ny() const { return options_.ny; }
  double time_s() const { return time_s_; }
  long steps() const { return steps_; }
  const ActiveTileSummary& tile_summary() const { return tiles_summary_; }

  double height(int i, int j) const {
    const std::size_t k = index(i, j);
    return f64_ ? cur64_[k] : static_cast<double>(cur32_[k]);
  }
  // Where a draught patch's point (i, j) acts (model/water/draught_patch.hpp): wrapped onto the grid
  // on a periodic field (true); on any other, true only inside the grid (beyond the rim it is ignored).
  bool patch_point_on_grid(int& i, int& j) const {
    const int nx = options_.nx, ny = options_.ny;
    if (options_.boundary == Boundary::periodic) {
      i = ((i % nx) + nx) % nx;
      j = ((j % ny) + ny) % ny;
      return true;
    }
    return i >= 0 && i < nx && j >= 0 && j < ny;
  }
  // z at the previous time level.
  double previous_height(int i, int j) const {
    const std::size_t k = index(i, j);
    return f64_ ? prev64_[k] : static_cast<double>(prev32_[k]);
  }
  void set_height(int i, int j, double z);
  // Copies the current heights (row-major, x fastest) into out (resized to nx·ny).
  void heights(std::vector<double>& out) const;
  // Σ z d² over the grid (the water volume above z = 0), summed in double.
  double volume_m3() const;
  // Height at a point x = i d, y = j d in grid units (bilinear between cells); outside the grid,
  // periodic fields wrap, others take the nearest edge value.
  double interpolate(double x_m, double y_m) const;
  // The same at both time levels at once, {z(t), z(t − Δt)}: one set of weights for the two.
  std::pair<double, double> interpolate_both_levels(double x_m, double y_m) const;

 private:
  // Padded layout: row j (−G ≤ j < ny + G) starts at (j + G)·stride, G = ghost_rows_ (1, or the
  // periodic images of several levels for temporal blocking); its left ghost sits one before a
  // cache-line boundary (origin_), so cell (0, j) starts a line; stride is a whole number of lines.
  std::size_t index(int i, int j) const {
    return static_cast<std::size_t>(j + ghost_rows_) * stride_ + origin_ + static_cast<std::size_t>(i + 1);
  }
  std::size_t ghost_corner() const { return index(-1, -1); }  // where fill_ghosts' array starts
  template <class Real>
  void step_impl(std::vector<Real, CacheAligned<Real>>& cur, std::vector<Real, CacheAligned<Real>>& prev, const DraughtPatch* draught);
  template <class Real>
  void advance_blocked(std::vector<Real, CacheAligned<Real>>& cur, std::vector<Real, CacheAligned<Real>>& prev, long n);
  void build_forcing(const DraughtPatch& draught);
  int tile_of(int i, int j) const { return (j / options_.tiles.tile_cells) * tiles_x_ + i / options_.tiles.tile_cells; }
  void restart();  // after set_state/set_levels: time 0, every tile's activity measured
  void note_activity(int i, int j);  // raises cell (i, j)'s tile activity to its |z|, |z − z⁻|
  // The four cells around a point and their bilinear weights (interpolate's rule).
  struct Bilinear {
    int i0, i1, j0, j1;
    double w00, w10, w01, w11;  // w_ab: the weight of cell (i_a, j_b)
  };
  Bilinear bilinear(double x_m, double y_m) const;

  HeightFieldOptions options_;
  bool f64_ = true;
  std::size_t stride_ = 0, origin_ = 0, levels_size_ = 0;
  int ghost_rows_ = 1;
  std::vector<double, CacheAligned<double>> cur64_, prev64_;
  std::vector<float, CacheAligned<float>> cur32_, prev32_;
  double time_s_ = 0;
  long steps_ = 0;
  std::unique_ptr<ThreadTeam> team_;

  // Draught forcing: C = d² L[b] on the box [fi0, fi0 + fni) × [fj0, fj0 + fnj) (unwrapped).
  std::vector<double> forcing_;
  int fi0_ = 0, fj0_ = 0, fni_ = 0, fnj_ = 0;

  // Active tiles (model/README.md §2.6).
  int tiles_x_ = 0, tiles_y_ = 0;
  std::vector<unsigned char> holds_;      // max(|z|, |z − z⁻|) > ε in the tile
  std::vector<unsigned char> nonzero_;    // anything nonzero in the tile
  std::vector<unsigned char> step_flag_;  // scratch: the tiles this step updates
  std::vector<int> active_;
  std::vector<std::array<int, 9>> tile_neighbours_;  // 3(dy + 1) + dx + 1 → tile, −1 beyond the edge
  struct TileRun {
    int band, first, end;  // tiles [first, end) of tile row `band`
  };
  std::vector<TileRun> runs_;
  std::vector<double> activity64_;  // per tile, raised by the kernel (float64 storage)
  std::vector<float> activity32_;   // (float32 storage)
  ActiveTileSummary tiles_summary_;
};

}  // namespace stoneskip
