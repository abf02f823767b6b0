fn main() -> std::process::ExitCode {
    cad2mo::main()
}
