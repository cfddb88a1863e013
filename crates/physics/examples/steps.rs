//! Steps a scene for counting instructions: `steps SCENE SETTLE STEPS` loads the scene, takes
//! `SETTLE` steps, then `STEPS` more. Under `valgrind --tool=callgrind`, the difference between
//! two step counts divided by the difference of steps is the cost of one step, repeatable to the
//! instruction whatever else the machine is doing (the `step` bench measures seconds).

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args: Vec<String> = std::env::args().collect();
    let [_, scene, settle, steps] = args.as_slice() else { return Err("usage: steps SCENE SETTLE STEPS".into()) };
    let mut world = tether_scene::load(std::path::Path::new(scene))?.world;
    for _ in 0..settle.parse::<usize>()? + steps.parse::<usize>()? {
        world.step()?;
    }
    println!("t = {} s", world.time());
    Ok(())
}
