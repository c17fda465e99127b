// Sample 8: rollback netcode between two peers in one process (docs/rollback.md). Each
// pane is one peer's world of the same arena: you steer the left runner on peer A, a
// scripted player steers the right one on peer B. Each peer hears the other's keys
// kDelay frames late; until then it guesses they are still the last ones it heard, steps
// on, and when the real ones differ it restores its snapshot of that frame and steps
// again to now. The titles show, for the last frame both peers know all the keys of,
// each peer's state hash (its first 8 digits): the same, bit for bit, however often they
// guessed wrong.
#include "runner.hpp"
#include "sample_list.hpp"

#include <array>
#include <cinttypes>
#include <cstdio>
#include <deque>
#include <vector>

namespace jostle::demo {

namespace {

constexpr JumpDef kJump{.height = 90.0f, .timeToApex = 0.35f};
constexpr float kRunSpeed = 200.0f;
/// Frames a peer's keys take to reach the other peer: 100 ms at 60 steps a second.
constexpr int kDelay = 6;

/// The keys of both players in one frame.
struct Keys {
    Controls of[2];
};

bool operator==(const Controls& a, const Controls& b) {
    return a.left == b.left && a.right == b.right && a.up == b.up && a.down == b.down &&
           a.jumpPressed == b.jumpPressed;
}

/// Peer B's player: runs to and fro and jumps now and then, by the frame number alone.
Controls scriptedKeys(int frame) {
    Controls keys;
    const int phase = frame % 240;
    keys.left = phase < 110;
    keys.right = phase >= 120 && phase < 230;
    keys.jumpPressed = frame % 90 == 45;
    return keys;
}

/// One peer: its world, and what it keeps to roll back.
struct Peer {
    World* world = nullptr;
    Runner runners[2];
    int local = 0;          ///< the player whose keys this peer reads itself
    int heardUpTo = -1;     ///< the last frame whose remote keys have arrived
    std::vector<Keys> used; ///< by frame: the keys each step was taken with
    /// By frame: the state before the frame's step (what a rollback restores).
    std::deque<std::vector<std::byte>> before;
    int firstKept = 0; ///< the frame of before.front()
    int rollbacks = 0;

    std::vector<std::byte>& snapshotOf(int frame) {
        return before[static_cast<std::size_t>(frame - firstKept)];
    }
    /// Steps the frame's keys into the world (the step itself is the demo's).
    void apply(const Keys& keys) {
        for (int p = 0; p < 2; ++p)
            runners[p].steer(*world, keys.of[p]);
    }
};

class RollbackSample : public Sample {
public:
    const char* name() const override { return "rollback"; }
    bool usesLetterKeys() const override { return true; }
    BodyId player() const override { return peers_[0].runners[0].body(); }
    /// The last confirmed frame, whether both peers' states of it are the same, and how
    /// many rollbacks each made.
    void report() const override {
        std::printf("confirmed_frame %d\npeers_agree %d\nrollbacks_a %d\nrollbacks_b %d\n",
                    confirmed_, agree_ ? 1 : 0, peers_[0].rollbacks, peers_[1].rollbacks);
    }

    void reset() override {
        panes_.clear();
        frame_ = 0;
        confirmed_ = -1;
        agree_ = true;
        keys_.clear();
        for (int p = 0; p < 2; ++p) {
            Pane pane = paneWithWorld({.gravity = {0.0f, kJump.gravity()}});
            Peer& peer = peers_[p];
            peer = Peer{};
            peer.world = pane.world.get();
            peer.local = p;
            const BodyId players[2] = {arena(*peer.world, 0), arena(*peer.world, 1)};
            for (int q = 0; q < 2; ++q)
                peer.runners[q] = Runner(players[q], kRunSpeed, kJump);
            pane.labels.push_back({players[0], "A"});
            pane.labels.push_back({players[1], "B"});
            pane.view = withHeadroom(boundsOf(*peer.world), 0.3f);
            pane.title = p == 0 ? "PEER A" : "PEER B";
            panes_.push_back(std::move(pane));
        }
    }

    void beforeStep(const Controls& controls, float dt) override {
        keys_.push_back({{controls, scriptedKeys(frame_)}});
        for (int p = 0; p < 2; ++p)
            prepare(peers_[p], dt);
        showConfirmedHashes();
        ++frame_;
    }

private:
    /// A floor, walls, crates between the two players, and the players: the same arena in
    /// both worlds, made in the same order, so that its handles are the same too.
    static BodyId arena(World& world, int player) {
        if (player == 0) {
            world.createBody({.type = BodyType::Static, .x = 320, .y = 410, .hw = 330, .hh = 10});
            world.createBody({.type = BodyType::Static, .x = -20, .y = 300, .hw = 10, .hh = 120});
            world.createBody({.type = BodyType::Static, .x = 660, .y = 300, .hw = 10, .hh = 120});
            world.createBody({.type = BodyType::Static,
                              .x = 320,
                              .y = 330,
                              .hw = 60,
                              .hh = 5,
                              .oneWay = {0.0f, -1.0f}});
            for (int i = 0; i < 6; ++i)
                world.createBody({.x = 250.0f + 28.0f * float(i % 3),
                                  .y = 386.0f - 28.0f * float(i / 3),
                                  .hw = 13,
                                  .hh = 13,
                                  .friction = 0.6f,
                                  .mass = 1.0f});
        }
        return world.createBody({.x = player == 0 ? 60.0f : 580.0f,
                                 .y = 380,
                                 .hw = 10,
                                 .hh = 18,
                                 .friction = 0.8f,
                                 .mass = 2.0f,
                                 .character = true});
    }

    /// Readies `peer` for this frame's step: hears the remote keys of kDelay frames ago,
    /// rolls back and steps again if they differ from its guess, then snapshots the state
    /// before this frame and applies this frame's keys, guessed where not yet heard.
    void prepare(Peer& peer, float dt) {
        const int remote = 1 - peer.local;
        const int heard = frame_ - kDelay; // the frame whose remote keys arrive now
        if (heard >= 0) {
            peer.heardUpTo = heard;
            const Controls& real = keys_[static_cast<std::size_t>(heard)].of[remote];
            if (!(peer.used[static_cast<std::size_t>(heard)].of[remote] == real)) {
                ++peer.rollbacks;
                peer.world->restore(peer.snapshotOf(heard));
                for (int f = heard; f < frame_; ++f) {
                    Keys& keys = peer.used[static_cast<std::size_t>(f)];
                    keys.of[remote] = guess(peer, f);
                    std::vector<std::byte>& before = peer.snapshotOf(f);
                    before.resize(peer.world->snapshotSize());
                    peer.world->snapshot(before);
                    peer.apply(keys);
                    peer.world->step(dt);
                }
            }
        }
        Keys keys;
        keys.of[peer.local] = keys_[static_cast<std::size_t>(frame_)].of[peer.local];
        keys.of[remote] = guess(peer, frame_);
        peer.used.push_back(keys);
        peer.before.emplace_back(peer.world->snapshotSize());
        peer.world->snapshot(peer.before.back());
        // Keep what a rollback may need: kDelay frames back, and the confirmed one.
        while (peer.before.size() > kDelay + 2) {
            peer.before.pop_front();
            ++peer.firstKept;
        }
        peer.apply(keys);
    }

    /// The remote keys `peer` steps frame `f` with: the real ones if heard, else the last
    /// heard (no jump: a press is one frame's).
    Controls guess(const Peer& peer, int f) const {
        const int remote = 1 - peer.local;
        if (f <= peer.heardUpTo)
            return keys_[static_cast<std::size_t>(f)].of[remote];
        if (peer.heardUpTo < 0)
            return {};
        Controls last = keys_[static_cast<std::size_t>(peer.heardUpTo)].of[remote];
        last.jumpPressed = false;
        return last;
    }

    /// The titles: each peer's state after the last frame whose keys both have heard (the
    /// state before the next one, in its snapshot), and whether the two agree.
    void showConfirmedHashes() {
        const int confirmed = frame_ - kDelay; // both peers stepped it with the real keys
        if (confirmed < peers_[0].firstKept + 1 || confirmed < 1)
            return;
        std::uint64_t hashes[2];
        for (int p = 0; p < 2; ++p) {
            const std::vector<std::byte>& bytes = peers_[p].snapshotOf(confirmed);
            hashes[p] = 0;
            for (int i = 7; i >= 0; --i) // the header's checksum: the state hash
                hashes[p] =
                    hashes[p] << 8 | std::to_integer<std::uint64_t>(bytes[24 + std::size_t(i)]);
        }
        confirmed_ = confirmed - 1;
        agree_ = hashes[0] == hashes[1];
        for (int p = 0; p < 2; ++p) {
            char title[96];
            std::snprintf(title, sizeof title,
                          "PEER %c  frame %d  %016" PRIx64 "  %s  %d rollbacks", p == 0 ? 'A' : 'B',
                          confirmed - 1, hashes[p], hashes[0] == hashes[1] ? "same" : "DESYNC",
                          peers_[p].rollbacks);
            panes_[static_cast<std::size_t>(p)].title = title;
        }
    }

    Peer peers_[2];
    std::vector<Keys> keys_; ///< by frame: the keys each player pressed
    int frame_ = 0;
    int confirmed_ = -1; ///< the last frame whose states were compared
    bool agree_ = true;
};

} // namespace

std::unique_ptr<Sample> makeRollbackSample() {
    return std::make_unique<RollbackSample>();
}

} // namespace jostle::demo
