# SPDX-License-Identifier: MIT
# bash completion for raypoint. The commands and each command's options come from raypoint's own
# help (`raypoint --help`, `raypoint COMMAND --help`), so they cannot drift from the program.
_raypoint() {
    local cur prev words cword
    _init_completion || return
    if [[ $cword -eq 1 ]]; then
        COMPREPLY=($(compgen -W "$(raypoint --help 2>/dev/null |
            sed -n 's/^  \([a-z][a-z-]*\).*/\1/p') --help --version" -- "$cur"))
        return
    fi
    local command=${words[1]}
    case $prev in
    --config | --input | --annotate | --out | --control)
        _filedir
        return
        ;;
    --camera)
        COMPREPLY=($(compgen -W "auto $(compgen -G '/dev/video*') $(compgen -G '/dev/v4l/by-id/*')" -- "$cur"))
        return
        ;;
    esac
    if [[ $cur == -* ]]; then
        COMPREPLY=($(compgen -W "$(raypoint "$command" --help 2>/dev/null |
            sed -n 's/^ *\(--[a-z][a-z-]*\).*/\1/p')" -- "$cur"))
        return
    fi
    case $command in
    ctl) COMPREPLY=($(compgen -W "pause resume toggle recenter status" -- "$cur")) ;;
    *) _filedir ;;
    esac
}
complete -F _raypoint raypoint
