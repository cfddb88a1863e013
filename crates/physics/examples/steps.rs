//! Steps a scene for counting instructions: `steps SCENE SETTLE STEPS` loads the scene, takes
//! `SETTLE` steps, then `STEPS` more. Under `valgrind --tool=callgrind`, the difference between
//! two step counts divided by the difference of steps is the cost of one step, repeatable to the
//! instruction whatever else the machine is doing (the `step` bench measures seconds).
//! It ends with where the bodies are — the mean and the lowest height of their centres of mass
//! and their kinetic energy — which `scripts/mujoco-compare.sh` sets beside MuJoCo's chain.

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args: Vec<String> = std::env::args().collect();
    let [_, scene, settle, steps] = args.as_slice() else { return Err("usage: steps SCENE SETTLE STEPS".into()) };
    let mut world = tether_scene::load(std::path::Path::new(scene))?.world;
    for _ in 0..settle.parse::<usize>()? + steps.parse::<usize>()? {
        world.step()?;
    }
    let heights: Vec<f64> = world.synchronized_states().iter().map(|state| state.position.z).collect();
    let mean = heights.iter().sum::<f64>() / heights.len() as f64;
    let lowest = heights.iter().copied().fold(f64::INFINITY, f64::min);
    let kinetic = world.energy().kinetic;
    println!("t = {:.3} s: mean height {mean:.4} m, lowest {lowest:.4} m, kinetic energy {kinetic:.2} J", world.time());
    Ok(())
}
