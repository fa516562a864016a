#!/usr/bin/perl
# Names that a module's released checks header declares but that nothing released needs.
#
#   perl hidden_only_helpers.pl RELEASE
#
# For every autograder/moduleNN_*/NAME_checks.hpp of the tree RELEASE (a student release, or the
# instructor's copy: hidden/ folders are skipped either way), the header and its NAME_checks.cpp
# are split into their namespace-scope items (functions, types, constants; the anonymous
# namespace's too), each with its text. A name is needed when a released file of the module
# folder other than these two (a visible test) mentions it, or when the text of a needed item
# does (a helper that a needed helper calls). Every name the header declares that is not needed
# is printed as "HEADER: NAME" (with the header relative to RELEASE), and the exit status is 1;
# an item that only hidden tests use belongs in hidden/ with them. The module's headers are
# only included by its own test files, so uses elsewhere do not count.
#
# Names are matched as words, so a needed item that mentions a name in another sense (a member
# or a local of the same name) keeps it needed: the check can miss such a name, never blame a
# needed one.
use strict;
use warnings;

my $root = shift or die "usage: hidden_only_helpers.pl RELEASE\n";
$root =~ s{/+$}{};

sub slurp {
  my ($path) = @_;
  open(my $in, '<', $path) or die "hidden_only_helpers: cannot read $path: $!\n";
  local $/;
  my $text = <$in>;
  close $in;
  return $text;
}

# Code without comments, string literals and preprocessor lines.
sub code_of {
  my ($text) = @_;
  $text =~ s{/\*.*?\*/}{ }gs;
  $text =~ s{//[^\n]*}{}g;
  $text =~ s{"(?:\\.|[^"\\\n])*"}{""}g;
  $text =~ s{'(?:\\.|[^'\\\n])'}{' '}g;
  $text =~ s{^\s*#[^\n]*}{}mg;
  return $text;
}

# The name an item defines or declares, from the text before its body or its end.
sub name_of {
  my ($head) = @_;
  $head =~ s/\btemplate\s*<[^;{]*?>\s*//g;
  return $1 if $head =~ /^\s*(?:struct|class|union|enum(?:\s+class|\s+struct)?)\s+(\w+)/;
  return $1 if $head =~ /^\s*using\s+(\w+)\s*=/;
  return "operator" if $head =~ /\boperator\b/;  # used where its operands are: always needed
  return undef if $head =~ /^\s*using\b/;
  return $1 if $head =~ /(\w+)::~?\w+\s*\(/;  # a member defined outside its class belongs to it
  return $1 if $head =~ /(\w+)\s*\(/;
  return $1 if $head =~ /(\w+)\s*(?:=.*)?$/s;
  return undef;
}

# Namespace-scope items of a file: (name, text) pairs, namespaces opened through.
sub items_of {
  my ($text) = @_;
  $text = code_of($text);
  $text =~ s{\bnamespace(?:\s+[\w:]+)?\s*\{}{ }g;  # namespace braces do not open a scope here
  my @items;
  my ($depth, $item, $head) = (0, '', undef);
  for my $c (split //, $text) {
    $item .= $c;
    if ($c eq '{') {
      $head = $item if $depth == 0 && !defined $head;
      $depth++;
    } elsif ($c eq '}') {
      if ($depth == 0) { $item = ''; next }  # a namespace closes
      $depth--;
      # A function body ends the item; a type's or an initialiser's brace waits for its ';'.
      if ($depth == 0 && $head =~ /\)\s*(?:const\s*)?(?:noexcept\s*)?(?:->[^{]*)?\{$/s) {
        push @items, [name_of(substr($head, 0, -1)), $item];
        ($item, $head) = ('', undef);
      }
    } elsif ($c eq ';' && $depth == 0) {
      my $name = name_of(defined $head ? substr($head, 0, -1) : substr($item, 0, -1));
      push @items, [$name, $item];
      ($item, $head) = ('', undef);
    }
  }
  return grep { defined $_->[0] } @items;
}

sub words_of {
  my ($text) = @_;
  my %words = map { $_ => 1 } ($text =~ /\b([A-Za-z_]\w*)\b/g);
  return \%words;
}

my $found = 0;
for my $header (sort glob("$root/autograder/module[0-9][0-9]_*/*_checks.hpp")) {
  (my $folder = $header) =~ s{/[^/]+$}{};
  (my $source = $header) =~ s{\.hpp$}{.cpp};
  my @declared = items_of(slurp($header));
  my @items = (@declared, -f $source ? items_of(slurp($source)) : ());
  my %text;
  $text{$_->[0]} .= $_->[1] . "\n" for @items;

  # The roots: every word of the module's other released files (hidden/ left out).
  my %roots;
  my @files = (glob("$folder/*"), glob("$folder/visible/*"));
  for my $file (grep { -f $_ && $_ ne $header && $_ ne $source } @files) {
    %roots = (%roots, %{ words_of(code_of(slurp($file))) });
  }
  $roots{operator} = 1;  # an operator is used wherever its operands are
  my %needed;
  my @queue = grep { $roots{$_} } keys %text;
  while (my $name = shift @queue) {
    next if $needed{$name}++;
    my $words = words_of($text{$name});
    push @queue, grep { $words->{$_} && !$needed{$_} } keys %text;
  }
  my %seen;
  for my $name (sort map { $_->[0] } @declared) {
    next if $needed{$name} || $seen{$name}++;
    (my $shown = $header) =~ s{^\Q$root\E/}{};
    print "$shown: $name\n";
    $found = 1;
  }
}
exit $found;
