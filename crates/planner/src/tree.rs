//! The node arena of the VORRT tree.
//!
//! Every node holds ownship's state and its time; the targets' states at that
//! time are predicted in closed form from the root (`vorrt_jfs::LinearTrack`)
//! rather than stored, and the encounters in force are kept in one flat
//! array, `targets` entries a node. Buffers are sized once per plan and
//! reused, so growing the tree allocates nothing.

use crate::config::NearestIndex;
use crate::plan::RejectionCause;
use glam::DVec2;
use rstar::RTree;
use rstar::primitives::GeomWithData;
use vorrt_colregs::EncounterLatch;
use vorrt_jfs::Pose;

type IndexedPoint = GeomWithData<[f64; 2], u32>;

/// Side of a cell of [`NearestIndex::Grid`], metres (16 steps of the
/// default `d'`): of 400, 800, 1600 and 3200 m, the one whose nearest-node
/// queries took the smallest share of the closed loop on `imazu_13`, 16, 17
/// and 20 (`docs/history/performance.md`).
const GRID_CELL_M: f64 = 1600.0;

/// The nodes that fall in one cell of the grid, with their bounding box.
#[derive(Debug, Clone)]
struct Cell {
    min_m: DVec2,
    max_m: DVec2,
    nodes: Vec<u32>,
}

impl Cell {
    /// Squared distance from `point_m` to the box: no node of the cell is
    /// nearer.
    fn lower_bound(&self, point_m: DVec2) -> f64 {
        point_m
            .clamp(self.min_m, self.max_m)
            .distance_squared(point_m)
    }
}

/// The tree of joint states.
#[derive(Debug, Default)]
pub(crate) struct Tree {
    /// Ownship's position at each node, metres.
    pub(crate) positions: Vec<DVec2>,
    /// Ownship's course on the segment into each node, radians.
    pub(crate) courses: Vec<f64>,
    /// Unit vector of each node's course (x east, y north).
    pub(crate) headings: Vec<DVec2>,
    /// Time of each node, seconds.
    pub(crate) times: Vec<f64>,
    /// Parent of each node (the root is its own parent).
    pub(crate) parents: Vec<u32>,
    /// Encounters in force at each node: `latches[node * targets + target]`.
    pub(crate) latches: Vec<Option<EncounterLatch>>,
    /// For each encounter in force (same layout), the largest alteration of
    /// course from its reference made on the branch since it began, radians
    /// (rule 16: readily apparent).
    pub(crate) alterations: Vec<f64>,
    /// Why the move from each node straight for the goal was rejected, once
    /// tried: the same node and goal always give the same move, so a goal
    /// sample that picks it again is answered from here.
    pub(crate) goal_rejections: Vec<Option<RejectionCause>>,
    targets: usize,
    index: NearestIndex,
    rtree: RTree<IndexedPoint>,
    /// [`NearestIndex::Grid`]: the occupied cells, and each cell's place in
    /// `cells` by its integer coordinates.
    cells: Vec<Cell>,
    cell_of: std::collections::HashMap<(i64, i64), u32>,
    /// The goal and the cosine of the turn bound, for the two caches below.
    goal: Option<(DVec2, f64)>,
    /// `(distance², node)` of the node nearest the goal (oldest on ties).
    nearest_goal: Option<(f64, u32)>,
    /// The same among nodes that face the goal within one bounded turn.
    nearest_facing_goal: Option<(f64, u32)>,
}

impl Tree {
    /// Empties the tree and sizes its buffers for `capacity` nodes of `targets` targets.
    pub(crate) fn reset(&mut self, capacity: usize, targets: usize, index: NearestIndex) {
        self.positions.clear();
        self.courses.clear();
        self.headings.clear();
        self.times.clear();
        self.parents.clear();
        self.latches.clear();
        self.alterations.clear();
        self.goal_rejections.clear();
        self.goal = None;
        self.nearest_goal = None;
        self.nearest_facing_goal = None;
        self.positions.reserve(capacity);
        self.courses.reserve(capacity);
        self.headings.reserve(capacity);
        self.times.reserve(capacity);
        self.parents.reserve(capacity);
        self.latches.reserve(capacity * targets);
        self.alterations.reserve(capacity * targets);
        self.goal_rejections.reserve(capacity);
        self.targets = targets;
        self.index = index;
        self.rtree = RTree::new();
        self.cells.clear();
        self.cell_of.clear();
    }

    /// Keeps, from now on, the nodes nearest `goal_m` (and nearest facing it
    /// within the turn whose cosine is `min_cos`) as they are added, so that
    /// [`nearest_facing_goal`](Self::nearest_facing_goal) costs nothing. Call
    /// after [`reset`](Self::reset), before the first node.
    pub(crate) fn set_goal(&mut self, goal_m: DVec2, min_cos: f64) {
        self.goal = Some((goal_m, min_cos));
    }

    /// [`nearest_facing`](Self::nearest_facing) for the goal given to
    /// [`set_goal`](Self::set_goal), from the kept answer (the same node the
    /// linear scan finds).
    #[must_use]
    pub(crate) fn nearest_facing_goal(&self) -> Option<u32> {
        self.nearest_facing_goal
            .or(self.nearest_goal)
            .map(|(_, index)| index)
    }

    /// Number of nodes.
    #[must_use]
    pub(crate) fn len(&self) -> usize {
        self.positions.len()
    }

    /// Where `node` lies and the course it was reached on.
    #[must_use]
    pub(crate) fn pose_of(&self, node: u32) -> Pose {
        Pose {
            position_m: self.positions[node as usize],
            course_rad: self.courses[node as usize],
        }
    }

    /// Adds a node and returns its index; `latches` and `alterations` hold
    /// one entry per target.
    #[expect(
        clippy::cast_possible_truncation,
        reason = "a tree holds at most 2 × MAX_NODES_PER_PHASE + 2 nodes and as many \
                  cells, so their indices fit u32; the cell key saturates far off, \
                  and a cell keeps its own exact box"
    )]
    pub(crate) fn push(
        &mut self,
        position_m: DVec2,
        course_rad: f64,
        time_s: f64,
        parent: u32,
        latches: &[Option<EncounterLatch>],
        alterations: &[f64],
    ) -> u32 {
        debug_assert_eq!(latches.len(), self.targets);
        debug_assert_eq!(alterations.len(), self.targets);
        let index = self.positions.len() as u32;
        self.positions.push(position_m);
        self.courses.push(course_rad);
        self.headings
            .push(vorrt_geometry::angle::course_to_unit(course_rad));
        self.times.push(time_s);
        self.parents.push(parent);
        self.latches.extend_from_slice(latches);
        self.alterations.extend_from_slice(alterations);
        self.goal_rejections.push(None);
        if let Some((goal_m, min_cos)) = self.goal {
            let distance = position_m.distance_squared(goal_m);
            if self.nearest_goal.is_none_or(|(best, _)| distance < best) {
                self.nearest_goal = Some((distance, index));
            }
            if faces(self.headings[index as usize], position_m, goal_m, min_cos)
                && self
                    .nearest_facing_goal
                    .is_none_or(|(best, _)| distance < best)
            {
                self.nearest_facing_goal = Some((distance, index));
            }
        }
        match self.index {
            NearestIndex::RTree => self
                .rtree
                .insert(IndexedPoint::new([position_m.x, position_m.y], index)),
            NearestIndex::Grid => {
                let key = (
                    (position_m.x / GRID_CELL_M).floor() as i64,
                    (position_m.y / GRID_CELL_M).floor() as i64,
                );
                let cells = &mut self.cells;
                let cell = *self.cell_of.entry(key).or_insert_with(|| {
                    cells.push(Cell {
                        min_m: position_m,
                        max_m: position_m,
                        nodes: Vec::new(),
                    });
                    (cells.len() - 1) as u32
                });
                let cell = &mut self.cells[cell as usize];
                cell.min_m = cell.min_m.min(position_m);
                cell.max_m = cell.max_m.max(position_m);
                cell.nodes.push(index);
            }
            NearestIndex::Linear => {}
        }
        index
    }

    /// The encounters in force at `node`.
    #[must_use]
    pub(crate) fn latches_of(&self, node: u32) -> &[Option<EncounterLatch>] {
        let start = node as usize * self.targets;
        &self.latches[start..start + self.targets]
    }

    /// The alterations made for the encounters in force at `node`.
    #[must_use]
    pub(crate) fn alterations_of(&self, node: u32) -> &[f64] {
        let start = node as usize * self.targets;
        &self.alterations[start..start + self.targets]
    }

    /// The node nearest to `point_m` (Algorithm 2, `getClosestNode`); ties go
    /// to the older node. `None` only for an empty tree.
    #[must_use]
    #[expect(
        clippy::cast_possible_truncation,
        reason = "a tree holds at most 2 × MAX_NODES_PER_PHASE + 2 nodes, so node indices fit u32"
    )]
    pub(crate) fn nearest(&self, point_m: DVec2) -> Option<u32> {
        match self.index {
            NearestIndex::Linear => {
                let mut best = None;
                let mut best_distance = f64::INFINITY;
                for (index, position) in self.positions.iter().enumerate() {
                    let distance = position.distance_squared(point_m);
                    if distance < best_distance {
                        best_distance = distance;
                        best = Some(index as u32);
                    }
                }
                best
            }
            NearestIndex::RTree => self
                .rtree
                .nearest_neighbor(&[point_m.x, point_m.y])
                .map(|entry| entry.data),
            NearestIndex::Grid => self.nearest_in_grid(point_m),
        }
    }

    /// [`nearest`](Self::nearest) through the grid, with the linear scan's
    /// answer: the cell whose box is nearest is scanned first, then every
    /// cell whose box is no farther than the best node so far, comparing
    /// (distance, index) so that ties go to the older node in any order of
    /// visit. A cell skipped lies wholly farther than that node.
    #[expect(
        clippy::float_cmp,
        reason = "an exact tie in distance goes to the older node, as in the linear scan"
    )]
    fn nearest_in_grid(&self, point_m: DVec2) -> Option<u32> {
        let first = self
            .cells
            .iter()
            .min_by(|a, b| a.lower_bound(point_m).total_cmp(&b.lower_bound(point_m)))?;
        let mut best = (f64::INFINITY, u32::MAX);
        let scan = |cell: &Cell, best: &mut (f64, u32)| {
            for &index in &cell.nodes {
                let distance = self.positions[index as usize].distance_squared(point_m);
                if distance < best.0 || (distance == best.0 && index < best.1) {
                    *best = (distance, index);
                }
            }
        };
        scan(first, &mut best);
        for cell in &self.cells {
            if !std::ptr::eq(cell, first) && cell.lower_bound(point_m) <= best.0 {
                scan(cell, &mut best);
            }
        }
        Some(best.1)
    }

    // The scan that `nearest_facing_goal`'s kept answer is tested against.
    #[cfg(test)]
    /// The node nearest to `point_m` among those that can head for it within
    /// one bounded turn: the angle between the node's course and the
    /// direction to the point is at most `acos(min_cos)`. Falls back to
    /// [`nearest`](Self::nearest) when no node faces the point. Ties go to the
    /// older node, whichever index is used.
    #[must_use]
    #[expect(
        clippy::cast_possible_truncation,
        reason = "a tree holds at most 2 × MAX_NODES_PER_PHASE + 2 nodes, so node indices fit u32"
    )]
    pub(crate) fn nearest_facing(&self, point_m: DVec2, min_cos: f64) -> Option<u32> {
        let faces = |index: usize| {
            faces(
                self.headings[index],
                self.positions[index],
                point_m,
                min_cos,
            )
        };
        match self.index {
            NearestIndex::Linear | NearestIndex::Grid => {
                let mut best = None;
                let mut best_distance = f64::INFINITY;
                for (index, position) in self.positions.iter().enumerate() {
                    let distance = position.distance_squared(point_m);
                    if distance < best_distance && faces(index) {
                        best_distance = distance;
                        best = Some(index as u32);
                    }
                }
                best.or_else(|| self.nearest(point_m))
            }
            NearestIndex::RTree => {
                let query = [point_m.x, point_m.y];
                let mut best: Option<(f64, u32)> = None;
                for entry in self.rtree.nearest_neighbor_iter(&query) {
                    let index = entry.data;
                    let distance = self.positions[index as usize].distance_squared(point_m);
                    if let Some((best_distance, best_index)) = best {
                        if distance > best_distance {
                            break;
                        }
                        if index < best_index && faces(index as usize) {
                            best = Some((distance, index));
                        }
                    } else if faces(index as usize) {
                        best = Some((distance, index));
                    }
                }
                best.map(|(_, index)| index)
                    .or_else(|| self.nearest(point_m))
            }
        }
    }

    /// The branch from the root to `node`, root first.
    #[must_use]
    pub(crate) fn branch(&self, node: u32) -> Vec<u32> {
        let mut branch = vec![node];
        let mut current = node;
        while self.parents[current as usize] != current {
            current = self.parents[current as usize];
            branch.push(current);
        }
        branch.reverse();
        branch
    }
}

/// Whether a node at `position_m` heading along `heading` can head for
/// `point_m` within the turn whose cosine is `min_cos`.
#[inline]
fn faces(heading: DVec2, position_m: DVec2, point_m: DVec2, min_cos: f64) -> bool {
    let offset = point_m - position_m;
    heading.dot(offset) >= min_cos * offset.length()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn grid_gives_the_linear_scans_answer_ties_included() {
        let mut linear = Tree::default();
        let mut grid = Tree::default();
        linear.reset(512, 0, NearestIndex::Linear);
        grid.reset(512, 0, NearestIndex::Grid);
        // Points on a 100 m lattice spanning many cells, each twice (ties:
        // the older copy must win).
        for i in 0..400u32 {
            let position = DVec2::new(
                f64::from(i * 37 % 101) * 100.0 - 3000.0,
                f64::from(i * 53 % 97) * 100.0 - 4000.0,
            );
            for _ in 0..2 {
                linear.push(position, 0.0, 0.0, 0, &[], &[]);
                grid.push(position, 0.0, 0.0, 0, &[], &[]);
            }
        }
        for i in 0..500u32 {
            let probe = DVec2::new(
                f64::from(i * 7919 % 20011) - 10000.0,
                f64::from(i * 104_729 % 30011) - 15000.0,
            );
            assert_eq!(grid.nearest(probe), linear.nearest(probe), "{probe}");
        }
        // On a lattice point between nodes: equal distances, oldest wins.
        for probe in [DVec2::new(-2950.0, -3950.0), DVec2::new(50.0, 50.0)] {
            assert_eq!(grid.nearest(probe), linear.nearest(probe), "{probe}");
        }
    }

    #[test]
    #[expect(
        clippy::float_cmp,
        reason = "both indices must find a node at exactly the nearest distance"
    )]
    fn linear_and_rtree_agree() {
        let mut linear = Tree::default();
        let mut indexed = Tree::default();
        linear.reset(64, 0, NearestIndex::Linear);
        indexed.reset(64, 0, NearestIndex::RTree);
        for i in 0..50u32 {
            let position = DVec2::new(f64::from(i * 37 % 101), f64::from(i * 53 % 97));
            linear.push(position, 0.0, 0.0, 0, &[], &[]);
            indexed.push(position, 0.0, 0.0, 0, &[], &[]);
        }
        for probe in [
            DVec2::new(3.3, 7.1),
            DVec2::new(90.0, 12.0),
            DVec2::new(50.5, 50.5),
        ] {
            let a = linear.nearest(probe).unwrap();
            let b = indexed.nearest(probe).unwrap();
            assert_eq!(
                linear.positions[a as usize].distance(probe),
                indexed.positions[b as usize].distance(probe)
            );
        }
    }

    #[test]
    fn facing_nearest_skips_nodes_pointing_away() {
        for index in [
            NearestIndex::Linear,
            NearestIndex::RTree,
            NearestIndex::Grid,
        ] {
            let mut tree = Tree::default();
            tree.reset(4, 0, index);
            // Nearest to the point, but heading south, away from it.
            tree.push(
                DVec2::new(0.0, 90.0),
                std::f64::consts::PI,
                0.0,
                0,
                &[],
                &[],
            );
            tree.push(DVec2::new(0.0, 50.0), 0.0, 0.0, 0, &[], &[]);
            let point = DVec2::new(0.0, 100.0);
            assert_eq!(tree.nearest(point), Some(0));
            assert_eq!(tree.nearest_facing(point, 0.5), Some(1));
            // Nobody faces a point due east at 90°+: fall back to the nearest.
            assert_eq!(tree.nearest_facing(DVec2::new(1000.0, 70.0), 0.9), Some(0));
        }
    }

    #[test]
    fn branch_runs_root_first() {
        let mut tree = Tree::default();
        tree.reset(4, 0, NearestIndex::Linear);
        tree.push(DVec2::ZERO, 0.0, 0.0, 0, &[], &[]);
        tree.push(DVec2::X, 0.0, 1.0, 0, &[], &[]);
        tree.push(DVec2::Y, 0.0, 2.0, 1, &[], &[]);
        assert_eq!(tree.branch(2), vec![0, 1, 2]);
    }

    #[test]
    fn kept_goal_answer_equals_the_scan() {
        let goal = DVec2::new(0.0, 1000.0);
        let min_cos = 30f64.to_radians().cos();
        let mut tree = Tree::default();
        tree.reset(64, 0, NearestIndex::Linear);
        tree.set_goal(goal, min_cos);
        for i in 0..60u32 {
            let position = DVec2::new(f64::from(i * 37 % 101) - 50.0, f64::from(i * 53 % 97) * 9.0);
            let course = f64::from(i * 71 % 360).to_radians();
            tree.push(position, course, 0.0, 0, &[], &[]);
            assert_eq!(
                tree.nearest_facing_goal(),
                tree.nearest_facing(goal, min_cos),
                "after {i}"
            );
        }
    }
}
