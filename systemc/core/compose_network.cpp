#include "systemc/core/compose_network.hpp"

#include <chrono>
#include <exception>
#include <stdexcept>
#include <systemc>

#include "golden/slice_steps.hpp"
#include "golden/units/compose.hpp"
#include "systemc/core/clocked_tops.hpp"
#include "systemc/rtl/rtl_factory.hpp"

#ifdef CUBE4_HAVE_RTL
#include "systemc/rtl/rtl_model.hpp"
#include "systemc/rtl/vl_context.hpp"
#include "systemc/rtl/vl_coverage.hpp"
#endif

namespace cube4::sysc {

namespace {

// A fixed delay of d cycles (d = 0: none): the registers of a pipeline.
template <class T>
class Delay {
 public:
  explicit Delay(int d = 0) : line_(static_cast<size_t>(d)) {}
  T shift(const T& in) {
    if (line_.empty()) return in;
    T out = line_[at_];
    line_[at_] = in;
    at_ = (at_ + 1) % line_.size();
    return out;
  }

 private:
  std::vector<T> line_;
  size_t at_ = 0;
};

class TlmComposeNode final : public ComposeNodeIf {
 public:
  TlmComposeNode(golden::BlendMode mode, const golden::Precision& p)
      : mode_(mode), p_(p), pipe_(kComposeNodeLatency) {}
  NodeBeat clock(const NodeBeat& front, const NodeBeat& back) override {
    NodeBeat out;
    out.valid = front.valid;
    if (out.valid) out.px = golden::compose(mode_, front.px, back.px, p_);
    return pipe_.shift(out);
  }
  Level level() const override { return Level::Tlm; }

 private:
  golden::BlendMode mode_;
  golden::Precision p_;
  Delay<NodeBeat> pipe_;
};

class TlmComposeOut final : public ComposeOutIf {
 public:
  explicit TlmComposeOut(const golden::Precision& p) : p_(p), pipe_(kComposeOutLatency) {}
  OutBeat clock(const NodeBeat& in) override {
    OutBeat out;
    out.valid = in.valid;
    if (in.valid) out.px = golden::pixel_of(in.px, p_);
    return pipe_.shift(out);
  }

 private:
  golden::Precision p_;
  Delay<OutBeat> pipe_;
};

int tree_depth(int n) {
  int d = 0;
  while ((1 << d) < n) ++d;
  return d;
}

// The tree of golden compose_tree(): the front half's tree over the back
// half's. Links 0 .. N-1 are the machines' (leaves), N .. the nodes'.
struct Tree {
  struct Node {
    int front = 0, back = 0;  // links
    int height = 0;
    Delay<NodeBeat> skew_front, skew_back;
    std::unique_ptr<ComposeNodeIf> unit;
  };
  std::vector<Node> nodes;
  int leaves = 0;
  int root = 0;  // the link the output stage reads

  // Returns the link of the tree over leaves [lo, lo + n) and its height.
  std::pair<int, int> build(int lo, int n) {
    if (n == 1) return {lo, 0};
    const int front = (n + 1) / 2;
    const auto f = build(lo, front), b = build(lo + front, n - front);
    Node node;
    node.front = f.first;
    node.back = b.first;
    node.height = 1 + std::max(f.second, b.second);
    const int hop = kComposeNodeLatency + 1;
    node.skew_front = Delay<NodeBeat>((node.height - 1 - f.second) * hop);
    node.skew_back = Delay<NodeBeat>((node.height - 1 - b.second) * hop);
    nodes.push_back(std::move(node));
    return {leaves + static_cast<int>(nodes.size()) - 1, nodes.back().height};
  }
};

// One run of the network: its links, units and progress through the image.
struct NetworkRun {
  const golden::BlockPlan& plan;
  const std::vector<const golden::BasePlane*>& partials;
  Tree tree;
  std::unique_ptr<ComposeOutIf> out;
  std::vector<NodeBeat> links, next;
  golden::BasePlane plane;
  uint64_t pixels = 0, written = 0, cycle = 0, done_cycle = 0;
  golden::Progress progress;
  bool done = false;

  NetworkRun(const golden::BlockPlan& pl, const std::vector<const golden::BasePlane*>& parts)
      : plan(pl), partials(parts), plane(golden::empty_base_plane(pl.whole)) {
    tree.leaves = static_cast<int>(pl.blocks.size());
    tree.root = tree.build(0, tree.leaves).first;
    links.resize(static_cast<size_t>(tree.leaves) + tree.nodes.size());
    next = links;
    pixels = static_cast<uint64_t>(plane.width) * plane.height;
  }

  // Leaf i's pixel at pixel index `at` of the volume's base plane: the
  // partial pixel there of the i-th block in the ray's visibility order (in
  // perspective the leaves' routing from the machines changes with the ray's
  // quadrant, BlockPlan::order_at(); in parallel projection leaf i is block i).
  golden::RayAcc leaf(int i, uint64_t at) const {
    const int pu = static_cast<int>(at % static_cast<uint64_t>(plane.width));
    const int pv = static_cast<int>(at / static_cast<uint64_t>(plane.width));
    const size_t k = static_cast<size_t>(plan.order_at(pu, pv)[static_cast<size_t>(i)]);
    const golden::Block& b = plan.blocks[k];
    const golden::BasePlane& part = *partials[k];
    const int u = pu - b.u0, v = pv - b.v0;
    if (u < 0 || v < 0 || u >= part.width || v >= part.height) return {};
    return part.acc[static_cast<size_t>(v) * part.width + u];
  }

  // One clock edge of every unit; each reads its links' values of this cycle.
  void edge() {
    ++cycle;
    const OutBeat o = out->clock(links[static_cast<size_t>(tree.root)]);
    if (o.valid) {
      if (written >= pixels) throw std::logic_error("composition network: more pixels than the base plane holds");
      golden::write_pixel(plane, static_cast<int>(written % static_cast<uint64_t>(plane.width)),
                          static_cast<int>(written / static_cast<uint64_t>(plane.width)), o.px);
      if (++written == pixels) {
        done = true;
        done_cycle = cycle;
      }
    }
    for (size_t n = 0; n < tree.nodes.size(); ++n) {
      Tree::Node& node = tree.nodes[n];
      const NodeBeat f = node.skew_front.shift(links[static_cast<size_t>(node.front)]);
      const NodeBeat b = node.skew_back.shift(links[static_cast<size_t>(node.back)]);
      if (f.valid != b.valid) throw std::logic_error("composition network: a node's inputs are not aligned");
      next[static_cast<size_t>(tree.leaves) + n] = node.unit->clock(f, b);
    }
    const uint64_t at = cycle - 1;
    for (int i = 0; i < tree.leaves; ++i)
      next[static_cast<size_t>(i)] = at < pixels ? NodeBeat{true, leaf(i, at)} : NodeBeat{};
    std::swap(links, next);
    if (progress && (cycle & 0xffff) == 0) progress(std::min(1.0, static_cast<double>(cycle) / pixels));
  }
};

// The network's clocked top: one process that clocks every node of the run
// plugged in, on the machine's clock (SystemC elaborates once, so it is
// built with the machine's top: build_clocked_tops()). Idle, it waits for
// the next run instead of waking every cycle.
SC_MODULE(NetworkTop) {
  NetworkRun* run = nullptr;
  std::exception_ptr error;
  sc_core::sc_event go;

  NetworkTop(sc_core::sc_module_name name, const EdgeClock& clk) : sc_core::sc_module(name) {
    SC_METHOD(step);
    sensitive << clk.posedge_event();
    dont_initialize();
  }
  SC_HAS_PROCESS(NetworkTop);

  void start(NetworkRun& r) {
    run = &r;
    error = nullptr;
    go.notify(sc_core::SC_ZERO_TIME);
  }
  void step() {
    if (!run) {
      next_trigger(go);
      return;
    }
    try {
      run->edge();
    } catch (...) {
      error = std::current_exception();
    }
    if (run->done || error) {
      run = nullptr;
      sc_core::sc_pause();
    }
  }
};

}  // namespace

NetworkCycles network_cycles(int width, int height, int blocks) {
  NetworkCycles c;
  c.nodes = blocks - 1;
  c.depth = tree_depth(blocks);
  c.stream = static_cast<uint64_t>(width) * height;
  c.latency = c.stream + 2 + static_cast<uint64_t>(c.depth) * (kComposeNodeLatency + 1);
  return c;
}

std::unique_ptr<ComposeNodeIf> make_tlm_compose_node(golden::BlendMode mode, const golden::Precision& p) {
  return std::make_unique<TlmComposeNode>(mode, p);
}
std::unique_ptr<ComposeOutIf> make_tlm_compose_out(const golden::Precision& p) {
  return std::make_unique<TlmComposeOut>(p);
}

sc_core::sc_module* build_network_top(const EdgeClock& clk) { return new NetworkTop("cube4_network", clk); }

NetworkResult run_network(const golden::BlockPlan& plan, const std::vector<const golden::BasePlane*>& partials,
                          const NetworkConfig& cfg, const golden::Progress& progress) {
  const auto t0 = std::chrono::steady_clock::now();
  // The shapes golden checks: one partial image per block, of its size.
  const golden::BasePlane want = golden::compose_blocks(plan, partials);
  NetworkResult res;
  const NetworkCycles nc = network_cycles(want.width, want.height, static_cast<int>(plan.blocks.size()));
  res.nodes = nc.nodes;
  res.depth = nc.depth;
  res.stream_cycles = nc.stream;
  res.level = cfg.level;
  res.clocked = cfg.level == Level::Rtl || cfg.cycle_level;
  if (!res.clocked) {
    res.plane = want;
    res.cycles = nc.latency;
  } else {
    // The context first: the models made in it must go before it does.
#ifdef CUBE4_HAVE_RTL
    rtl::ScopedVerilatedContext ctx(cfg.seed, !cfg.trace.file.empty(), cfg.assertions);
    VerilatedContext* rtl_ctx = ctx.get();
#else
    VerilatedContext* rtl_ctx = nullptr;
#endif
    NetworkRun run(plan, partials);
    run.progress = progress;
    const golden::Precision& p = plan.whole.p;
    for (size_t n = 0; n < run.tree.nodes.size(); ++n) {
      const bool root = static_cast<int>(plan.blocks.size() + n) == run.tree.root;
      run.tree.nodes[n].unit =
          cfg.level == Level::Rtl
              ? make_rtl_compose_node(plan.whole.blend, p, *rtl_ctx, root ? cfg.trace : TraceWindow{}, n)
              : make_tlm_compose_node(plan.whole.blend, p);
    }
    run.out = cfg.level == Level::Rtl ? make_rtl_compose_out(p, *rtl_ctx) : make_tlm_compose_out(p);
    if (cfg.kernel == Kernel::SystemC) {
      NetworkTop& top = dynamic_cast<NetworkTop&>(network_top());
      top.start(run);
      sc_core::sc_start();
      if (top.error) std::rethrow_exception(top.error);
    } else {
      while (!run.done) run.edge();
    }
    if (!run.done) throw std::logic_error("composition network: the simulation stopped before the last pixel");
    res.plane = std::move(run.plane);
    res.cycles = run.done_cycle;
#ifdef CUBE4_HAVE_RTL
    if (rtl_ctx) rtl::write_coverage(*rtl_ctx);  // while the models live (a coverage build's; else nothing)
#endif
  }
  if (cfg.check)
    for (size_t i = 0; i < want.rgba.size(); i += 4)
      if (!std::equal(&want.rgba[i], &want.rgba[i] + 4, &res.plane.rgba[i])) {
        const size_t px = i / 4;
        res.mismatch = "composition network, pixel (" + std::to_string(px % static_cast<size_t>(want.width)) + ", " +
                       std::to_string(px / static_cast<size_t>(want.width)) + "): expected RGBA (" +
                       std::to_string(want.rgba[i]) + ", " + std::to_string(want.rgba[i + 1]) + ", " +
                       std::to_string(want.rgba[i + 2]) + ", " + std::to_string(want.rgba[i + 3]) + "), got (" +
                       std::to_string(res.plane.rgba[i]) + ", " + std::to_string(res.plane.rgba[i + 1]) + ", " +
                       std::to_string(res.plane.rgba[i + 2]) + ", " + std::to_string(res.plane.rgba[i + 3]) + ")";
        break;
      }
  res.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (progress) progress(1.0);
  return res;
}

}  // namespace cube4::sysc
